#pragma once
// Robust numeric primitives in one place (numerical robustness: one implementation each). Callers
// never write a raw acos(dot(a, b)) or atan for a solid angle.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace luxgrid {

using Vec3 = glm::dvec3;
using Vec2 = glm::dvec2;

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kDegToRad = kPi / 180.0;
inline constexpr double kRadToDeg = 180.0 / kPi;

inline double safe_sqrt(double x) { return std::sqrt(std::max(0.0, x)); }
inline double safe_acos(double x) { return std::acos(std::clamp(x, -1.0, 1.0)); }
inline double safe_asin(double x) { return std::asin(std::clamp(x, -1.0, 1.0)); }

// Angle between two unit vectors from the half-chord: accurate near 0 and near pi, where
// acos(dot) loses half the digits.
inline double angle_between(const Vec3& a, const Vec3& b) {
  if (glm::dot(a, b) < 0) return kPi - 2.0 * safe_asin(glm::length(a + b) / 2.0);
  return 2.0 * safe_asin(glm::length(b - a) / 2.0);
}

}  // namespace luxgrid
