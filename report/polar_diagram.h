#pragma once
// The polar (goniometric) diagram of a luminaire: intensity in the C0-C180 plane (solid) and the
// C90-C270 plane (dashed) against the angle from nadir, nadir down, as an inline SVG.
#include <string>

#include "photometry/intensity_distribution.h"

namespace luxgrid::report {

// `size_px` is the square's side. The outer ring is a round value >= the largest intensity
// drawn, in cd.
std::string polar_diagram_svg(const photometry::IntensityDistribution& d, int size_px = 220);

}  // namespace luxgrid::report
