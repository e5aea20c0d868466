#include "report/map_frame.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "geometry/polygon.h"

namespace luxgrid::report {

namespace {

// 0.7 ~ cos 45 deg: a normal within 45 degrees of vertical is a horizontal surface (plan), one
// within ~0.6 degrees of horizontal is a vertical one (wall).
constexpr double kHorizontalNormalZ = 0.7, kVerticalNormalZ = 0.01;
// Surfaces on a room's boundary (walls, floor, ceiling) sit exactly on it; 1 mm of slack.
constexpr double kOnRoomTolerance_m = 1e-3;

const calc::Room* room_of(const geometry::SurfaceGrid& g, const calc::Scene* scene) {
  if (!scene) return nullptr;
  const Vec3 centre = g.origin + g.u_dir * (g.size_u / 2) + g.v_dir * (g.size_v / 2);
  for (const auto& room : scene->rooms) {
    if (centre.z < room.floor_z - kOnRoomTolerance_m ||
        centre.z > room.floor_z + room.height + kOnRoomTolerance_m)
      continue;
    if (geometry::locate(Vec2(centre), room.outline, kOnRoomTolerance_m) !=
        geometry::Location::outside)
      return &room;
  }
  return nullptr;
}

std::string xy(const Vec3& p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%.2f, %.2f)", p.x, p.y);
  return buf;
}

}  // namespace

void frame_coords(const MapFrame& f, const Vec3& world, double& a_m, double& b_m) {
  a_m = glm::dot(world - f.origin, f.right);
  b_m = glm::dot(world - f.origin, f.up);
}

MapFrame map_frame(const geometry::SurfaceGrid& g, const calc::Scene* scene) {
  MapFrame f;
  f.room = room_of(g, scene);
  const Vec3 n = glm::cross(g.u_dir, g.v_dir);
  const Vec3 corners[4] = {g.origin, g.origin + g.u_dir * g.size_u,
                           g.origin + g.u_dir * g.size_u + g.v_dir * g.size_v,
                           g.origin + g.v_dir * g.size_v};
  if (std::abs(n.z) >= kHorizontalNormalZ) {
    f.view = n.z > 0 ? MapFrame::View::plan : MapFrame::View::ceiling;
    f.right = {1, 0, 0};
    f.up = {0, 1, 0};
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    auto take = [&](double x, double y) {
      x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
    };
    for (const Vec3& c : corners) take(c.x, c.y);
    if (f.room)
      for (const Vec2& p : f.room->outline) take(p.x, p.y);
    const double z = (corners[0].z + corners[2].z) / 2;
    f.origin = {x0, y0, z};
    f.width_m = x1 - x0, f.height_m = y1 - y0;
    f.axis_x0 = x0, f.axis_y0 = y0;
    f.x_label = "x (m)", f.y_label = "y (m)";
    f.description = f.view == MapFrame::View::plan
                        ? "Seen from above, as the plan: x to the right, y (north) up."
                        : "Ceiling seen from below, drawn as a reflected ceiling plan (as in a "
                          "mirror on the floor) so "
                          "it lines up with the plan: x to the right, y (north) up.";
  } else {
    const bool vertical = std::abs(n.z) < kVerticalNormalZ;
    if (vertical) {
      f.view = MapFrame::View::wall;
      f.up = {0, 0, 1};
      // Looking at the surface against its normal, right = (-n) x up.
      f.right = glm::normalize(glm::cross(-n, f.up));
    } else {
      f.view = MapFrame::View::tilted;
      f.right = g.u_dir;
      f.up = g.v_dir;
    }
    double a0 = INFINITY, b0 = INFINITY, a1 = -INFINITY, b1 = -INFINITY;
    for (const Vec3& c : corners) {
      const double a = glm::dot(c, f.right), b = glm::dot(c, f.up);
      a0 = std::min(a0, a), b0 = std::min(b0, b), a1 = std::max(a1, a), b1 = std::max(b1, b);
    }
    // The lower-left corner: the corner with the smallest readings (a rectangle in its own plane).
    double lowest = INFINITY;
    for (const Vec3& c : corners) {
      const double s = glm::dot(c, f.right) + glm::dot(c, f.up);
      if (s < lowest) lowest = s, f.origin = c;
    }
    f.width_m = a1 - a0, f.height_m = b1 - b0;
    if (vertical) {
      f.axis_x0 = 0.0, f.axis_y0 = f.origin.z;
      f.x_label = "along the surface from its left end (m)", f.y_label = "z (m)";
      const Vec3 left = f.origin, right = f.origin + f.right * f.width_m;
      f.description =
          std::string(f.room ? "Seen from inside the room" : "Seen from the side it faces") +
          ", up at the top: left end at " + xy(left) + ", right end at " + xy(right) + ".";
    } else {
      f.axis_x0 = 0.0, f.axis_y0 = 0.0;
      f.x_label = "u (m)", f.y_label = "v (m)";
      f.description = "Seen from the side it faces, along its own u (right) and v (up).";
    }
  }
  f.width_m = std::max(f.width_m, 1e-3), f.height_m = std::max(f.height_m, 1e-3);
  return f;
}

}  // namespace luxgrid::report
