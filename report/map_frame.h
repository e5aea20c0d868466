#pragma once
// How a calculation surface is laid out on a picture: which world direction runs to the right and
// which up, the area drawn, what the axes measure and the view in words. One rule for every kind,
// so every map reads the same way:
// - horizontal, facing up (floors, workplanes): the plan, seen from above, +x right, +y up;
// - horizontal, facing down (ceilings): seen from below, drawn as a reflected ceiling plan (as in
//   a mirror on the floor), so it lines up with the plan: +x right, +y up;
// - vertical (walls): seen from the side the normal faces (a room's wall from inside the room),
//   up at the top, the horizontal axis measured from the left end;
// - tilted: along the surface's own u (right) and v (up), seen from the side its normal faces.
#include <string>

#include "calc/scene.h"
#include "geometry/surface_grid.h"

namespace luxgrid::report {

struct MapFrame {
  enum class View { plan, ceiling, wall, tilted };
  View view = View::plan;
  Vec3 origin{0.0};                  // world point at the lower-left corner of the drawn area
  Vec3 right{1, 0, 0}, up{0, 1, 0};  // unit world directions of image right and image up
  double width_m = 1.0, height_m = 1.0;
  double axis_x0 = 0.0, axis_y0 = 0.0;  // axis readings at `origin` (m)
  std::string x_label, y_label;         // "x (m)", "along the wall (m)", ...
  const calc::Room* room = nullptr;     // the room the surface lies in, or null
  std::string description;              // the view in words, for the map and the report
};

// The frame for `g`; `scene` (may be null) supplies the room whose outline the map also shows.
MapFrame map_frame(const geometry::SurfaceGrid& g, const calc::Scene* scene);

// The world point at (a, b) metres right of and above the frame's origin, and back.
inline Vec3 frame_point(const MapFrame& f, double a_m, double b_m) {  // inline: once a pixel
  return f.origin + f.right * a_m + f.up * b_m;
}
void frame_coords(const MapFrame& f, const Vec3& world, double& a_m, double& b_m);

}  // namespace luxgrid::report
