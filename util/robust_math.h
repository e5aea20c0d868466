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
inline constexpr double kTwoPi = 2.0 * kPi;
inline constexpr double kDegToRad = kPi / 180.0;
inline constexpr double kRadToDeg = 180.0 / kPi;

inline double safe_sqrt(double x) { return std::sqrt(std::max(0.0, x)); }
inline double safe_asin(double x) { return std::asin(std::clamp(x, -1.0, 1.0)); }

// Angle between two unit vectors from the half-chord: accurate near 0 and near pi, where
// acos(dot) loses half the digits.
inline double angle_between(const Vec3& a, const Vec3& b) {
  if (glm::dot(a, b) < 0) return kPi - 2.0 * safe_asin(glm::length(a + b) / 2.0);
  return 2.0 * safe_asin(glm::length(b - a) / 2.0);
}

// How many equal pieces cut an interval `ratio` times as wide as the widest piece allowed:
// ceil(ratio), but a ratio within 1e-9 above a whole number counts as that number. Widths are
// often exact multiples of the widest piece (15-degree C planes cut at 7.5 degrees, a 5-degree
// gamma cell at 5): rounding puts their ratio a few units in the last place above or below the
// whole number, and a plain ceil then gives one piece more or not at random, so two receivers a
// rounding apart got different cells (0.001 % apart under the office's luminaires).
inline int pieces_of_at_most(double ratio) {
  if (ratio <= 1.0) return 1;  // most calls: no piece wider than allowed (and no call of ceil)
  return std::max(1, static_cast<int>(std::ceil(ratio - 1e-9)));
}

}  // namespace luxgrid
