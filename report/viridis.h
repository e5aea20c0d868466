#pragma once
// The viridis colour map [vanderWaltSmith2015]: perceptually uniform and monotonic in lightness.
#include "report/raster.h"

namespace luxgrid::report {

// sRGB colour at t in [0, 1] (clamped): linear interpolation between 17 knots of the map.
Rgb viridis(double t);

}  // namespace luxgrid::report
