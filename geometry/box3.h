#pragma once
// Axis-aligned boxes on plain doubles: bounds of a plane height and of the distance over a box
// (the tile culling of calc/indirect's form-factor matrix and final gather) and the segment-box
// slab test (the obstacle filter of geometry/visibility.h).
#include <algorithm>
#include <utility>

#include <glm/common.hpp>

#include "util/robust_math.h"

namespace luxgrid::geometry {

struct Box3 {
  Vec3 lo{0.0}, hi{0.0};  // m
};

// Largest (smallest) of n . (v - x) over the box [lo, hi].
inline double box_max_height(const Vec3& n, const Vec3& x, const Vec3& lo, const Vec3& hi) {
  const Vec3 a = lo - x, b = hi - x;
  return std::max(n.x * a.x, n.x * b.x) + std::max(n.y * a.y, n.y * b.y) +
         std::max(n.z * a.z, n.z * b.z);
}
inline double box_min_height(const Vec3& n, const Vec3& x, const Vec3& lo, const Vec3& hi) {
  const Vec3 a = lo - x, b = hi - x;
  return std::min(n.x * a.x, n.x * b.x) + std::min(n.y * a.y, n.y * b.y) +
         std::min(n.z * a.z, n.z * b.z);
}
// Squared distance from x to the box [lo, hi].
inline double box_distance2(const Vec3& x, const Vec3& lo, const Vec3& hi) {
  const Vec3 d = glm::max(glm::max(lo - x, x - hi), Vec3(0.0));
  return glm::dot(d, d);
}

// True when the closed segment ab meets the box (slab test).
inline bool segment_meets_box(const Vec3& a, const Vec3& b, const Box3& box) {
  double t0 = 0.0, t1 = 1.0;
  const Vec3 d = b - a;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0) {
      if (a[k] < box.lo[k] || a[k] > box.hi[k]) return false;
      continue;
    }
    double ta = (box.lo[k] - a[k]) / d[k], tb = (box.hi[k] - a[k]) / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace luxgrid::geometry
