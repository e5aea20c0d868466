#pragma once
// The polar (goniometric) diagram of a luminaire, the one renderer behind `luxgrid info --plot`
// and the report's luminaire cards: intensity in the C0-C180 plane (solid, blue) and the
// C90-C270 plane (dashed, red) against the angle from nadir, nadir down; rings at quarters of a
// round outer value, each labelled in cd; spokes every 30 degrees with their angle; a title.
#include <string>
#include <vector>

#include "photometry/intensity_distribution.h"
#include "report/raster.h"

namespace luxgrid::report {

// What the diagram draws: the intensity (cd) in the C0-C180 and the C90-C270 plane at signed
// angles from nadir, -180 to 180 degrees in kPolarStepDeg steps (> 0 towards C0 and C90).
inline constexpr double kPolarStepDeg = 0.5;  // 721 samples a plane: smooth at 640 px, cheap
struct PolarCurves {
  std::vector<double> c0_cd, c90_cd;
};
PolarCurves polar_curves(const photometry::IntensityDistribution& d);

// The diagram of `curves` on a `size_px` square.
Raster polar_diagram(const PolarCurves& curves, const std::string& title, int size_px,
                     bool* font_ok = nullptr);
// The diagram of `d` on a `size_px` square. `font_ok` (if given) is set false when the labels could
// not be drawn for want of the font (the curves are drawn regardless).
Raster polar_diagram(const photometry::IntensityDistribution& d, const std::string& title,
                     int size_px, bool* font_ok = nullptr);

// The outer ring's value for a largest intensity of `imax_cd`: the round value >= it.
double polar_outer_ring_cd(double imax_cd);

}  // namespace luxgrid::report
