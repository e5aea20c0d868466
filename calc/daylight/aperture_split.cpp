#include "calc/daylight/aperture_split.h"

#include "geometry/polygon3.h"

namespace luxgrid::daylight {

std::vector<Triangle3> split_along_edges(const std::vector<Triangle3>& triangles, const Vec3& point,
                                         const std::vector<std::array<Vec3, 2>>& edges,
                                         const Vec3& beyond_origin, const Vec3& beyond_normal) {
  std::vector<geometry::Polygon3> pieces;
  for (const Triangle3& t : triangles) pieces.emplace_back(t.begin(), t.end());
  for (const auto& [a, b] : edges) {
    const double ha = glm::dot(a - beyond_origin, beyond_normal);
    const double hb = glm::dot(b - beyond_origin, beyond_normal);
    if (ha < 0.0 && hb < 0.0) continue;
    Vec3 n = glm::cross(a - point, b - point);
    const double length = glm::length(n);
    // In line with the point to 1e-12 of the edge's extent as seen from it.
    if (!(length > 1e-12 * glm::length(a - point) * glm::length(b - point))) continue;
    n /= length;
    std::vector<geometry::Polygon3> next;
    next.reserve(pieces.size() + 4);
    for (const geometry::Polygon3& p : pieces) {
      for (const double side : {1.0, -1.0}) {
        geometry::Polygon3 part = geometry::clip_to_half_space(p, point, side * n);
        if (part.size() >= 3) next.push_back(std::move(part));
      }
    }
    pieces = std::move(next);
  }
  std::vector<Triangle3> out;
  for (const geometry::Polygon3& p : pieces)
    for (std::size_t k = 1; k + 1 < p.size(); ++k) out.push_back({p[0], p[k], p[k + 1]});
  return out;
}

}  // namespace luxgrid::daylight
