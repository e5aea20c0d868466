#pragma once
// Bounds of n . (v - x) and of the distance from x over an axis-aligned box [lo, hi]: the tile
// culling of the form-factor matrix (radiosity.cpp) and of the final gather (indirect.cpp).
#include <algorithm>

#include <glm/common.hpp>

#include "util/robust_math.h"

namespace luxgrid::calc::indirect {

// Largest (smallest) of n . (v - x) over the box [lo, hi].
inline double box_max_height(const Vec3& n, const Vec3& x, const Vec3& lo, const Vec3& hi) {
  const Vec3 a = lo - x, b = hi - x;
  return std::max(n.x * a.x, n.x * b.x) + std::max(n.y * a.y, n.y * b.y) + std::max(n.z * a.z, n.z * b.z);
}
inline double box_min_height(const Vec3& n, const Vec3& x, const Vec3& lo, const Vec3& hi) {
  const Vec3 a = lo - x, b = hi - x;
  return std::min(n.x * a.x, n.x * b.x) + std::min(n.y * a.y, n.y * b.y) + std::min(n.z * a.z, n.z * b.z);
}
// Squared distance from x to the box [lo, hi].
inline double box_distance2(const Vec3& x, const Vec3& lo, const Vec3& hi) {
  const Vec3 d = glm::max(glm::max(lo - x, x - hi), Vec3(0.0));
  return glm::dot(d, d);
}

}  // namespace luxgrid::calc::indirect
