#pragma once
// The plan view of a room seen from above, as an inline SVG: outline, obstacles (footprints),
// luminaires with their aiming, the extents of the calculation grids, a north arrow (to true north:
// +y, the project's convention, unless a daylight site's north angle turns it) and a scale bar.
#include <string>
#include <vector>

#include "calc/scene.h"

namespace luxgrid::report {

// Draws `room` with every luminaire whose position lies over its outline (or within 0.5 m of its
// bounding box) and every grid surface that lies inside its bounding box; the room's obstacles
// as grey footprints (class "obstacle"); `openings`, the room's daylight openings (class
// "daylight-opening"): a window as a blue band over the part of its wall it takes, a roof light
// (or an opening in the floor) as its outline, dashed. `north_angle_deg`: true north, clockwise
// from +y (a daylight site's north angle, docs/daylight.md); the arrow points there.
std::string plan_view_svg(const calc::Room& room, const std::vector<calc::Luminaire>& luminaires,
                          const std::vector<geometry::SurfaceGrid>& surfaces, int width_px = 640,
                          const std::vector<calc::DaylightOpening>& openings = {},
                          double north_angle_deg = 0.0);

}  // namespace luxgrid::report
