#include "calc/points_in_openings.h"

#include <cmath>

#include "calc/opening_placement.h"
#include "geometry/polygon.h"

namespace luxgrid::calc {

void leave_out_points_in_openings(const Scene& scene, geometry::SurfaceGrid& g) {
  if (g.kind != geometry::SurfaceGrid::Kind::grid || g.points.empty()) return;
  const Vec3 grid_normal = glm::cross(g.u_dir, g.v_dir);
  for (const DaylightOpening& o : scene.openings) {
    // A grid is planar: only one lying in the opening's plane can hold points in it.
    const Vec3& corner = o.polygon.front();
    if (std::abs(std::abs(glm::dot(grid_normal, o.inward_normal)) - 1.0) > 1e-9 ||
        std::abs(glm::dot(g.origin - corner, o.inward_normal)) > kOpeningPlaneTolerance_m)
      continue;
    const Room& room = scene.rooms[o.room];
    const std::vector<Vec2> outline = face_coordinates(room, o.face, o.polygon);
    if (g.active.empty()) g.active.assign(g.points.size(), true);
    for (std::size_t i = 0; i < g.points.size(); ++i) {
      if (!g.active[i] ||
          std::abs(glm::dot(g.points[i] - corner, o.inward_normal)) > kOpeningPlaneTolerance_m)
        continue;
      const Vec2 at = face_coordinates(room, o.face, {g.points[i]}).front();
      if (geometry::locate(at, outline, kOpeningPlaneTolerance_m) != geometry::Location::inside)
        continue;
      g.active[i] = false;
      ++g.points_in_openings;
    }
  }
}

}  // namespace luxgrid::calc
