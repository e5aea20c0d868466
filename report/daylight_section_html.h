#pragma once
// report.html's daylight section (docs/report.md, "Daylight"), for the daylight scene only: the
// sky (type, E_h, the sun's altitude and azimuth), the site when the sun was computed from one,
// the openings with their glazing, and per surface the daylight factor: its statistics and, for
// grids, a false-colour map with contour lines at 1, 2 and 5 % (report/false_colour).
#include <string>
#include <vector>

#include "calc/results.h"
#include "calc/scene.h"

namespace luxgrid::report {

// The daylight factor's contour lines on the section's maps, percent: the round values a
// designer reads a daylight-factor map against (2 % the usual minimum average, 5 % a well
// daylit room, 1 % where a room's back turns dim).
inline const std::vector<double> kDaylightFactorLevels = {1.0, 2.0, 5.0};

// The section as HTML (its maps inline), or "" when the results are not of the daylight scene.
// `scene`: the openings, rooms and site; null: the sky and the maps alone.
std::string daylight_section_html(const calc::Results& results, const calc::Scene* scene);

}  // namespace luxgrid::report
