#pragma once
// The polar (goniometric) diagram of a luminaire, the one renderer behind `luxgrid info --plot`
// and the report's luminaire cards: intensity in the C0-C180 plane (solid, blue) and the
// C90-C270 plane (dashed, red) against the angle from nadir, nadir down; rings at quarters of a
// round outer value, each labelled in cd; spokes every 30 degrees with their angle; a title.
#include <string>

#include "photometry/intensity_distribution.h"
#include "report/raster.h"

namespace luxgrid::report {

// The diagram on a `size_px` square. `font_ok` (if given) is set false when the labels could not
// be drawn for want of the font (the curves are drawn regardless).
Raster polar_diagram(const photometry::IntensityDistribution& d, const std::string& title,
                     int size_px, bool* font_ok = nullptr);

// The outer ring's value for a largest intensity of `imax_cd`: the round value >= it.
double polar_outer_ring_cd(double imax_cd);

}  // namespace luxgrid::report
