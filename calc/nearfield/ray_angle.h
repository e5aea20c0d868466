#pragma once
// The angle of a ray of the table rung (table_cubature.cpp) from its sine and cosine, without atan
// and without a division: a ray from the receiver's foot reaches the opening at in-plane distance
// rho, so its receiver-side angle gamma' = atan(rho / |sigma|), with
// cos(gamma') = 1 / sqrt(1 + (rho / |sigma|)^2) and sin(gamma') = (rho / |sigma|) cos(gamma'), at
// both ends of every ray. The library's atan2 was a quarter of a workplane pair's time
// (docs/performance.md, "The near field under one panel").
//
// Reduction: with u = min(sin, cos) (angles up to 45 degrees; beyond, pi / 2 minus the angle of
// the swapped pair), the bin j = floor(kRayAngleBins sqrt(2) u) has a stored unit vector
// (s_j, c_j) at angle theta_j (computed once by atan2 from the stored doubles), and by the
// subtraction formula
//   angle = theta_j + asin(w),  w = sin(angle - theta_j) = u c_j - v s_j  (v the other one).
// d angle / d u = 1 / cos <= sqrt(2) up to 45 degrees, so a bin spans at most 1 / kRayAngleBins rad
// and |w| < 0.016. asin(w) is its Taylor series to w^11: the first omitted term,
// (63 / 2816) w^13, is below 1e-25, far below the rounding of theta_j (1e-16). The result agrees
// with std::atan2 to a few units in the last place (tests/nearfield/ray_angle_test.cpp).
#include <algorithm>
#include <array>
#include <cmath>

#include "util/robust_math.h"

namespace luxgrid::nearfield {

inline constexpr int kRayAngleBins = 64;

struct RayAngleBins {
  std::array<double, kRayAngleBins> sin_j, cos_j, theta_j;
  RayAngleBins() {
    for (int j = 0; j < kRayAngleBins; ++j) {
      sin_j[j] = j / (kRayAngleBins * std::sqrt(2.0));
      cos_j[j] = std::sqrt(1.0 - sin_j[j] * sin_j[j]);
      theta_j[j] = std::atan2(sin_j[j], cos_j[j]);
    }
  }
};

// Built at start-up (a namespace-scope object: no guard on every call, as a function's static has).
inline const RayAngleBins kRayAngleTable{};

// The angle in [0, pi / 4] whose sine is u and cosine v (u <= v, u^2 + v^2 = 1 to rounding).
inline double ray_angle_below_45(double u, double v) {
  const RayAngleBins& bins = kRayAngleTable;
  const int j =
      std::min(static_cast<int>(u * (kRayAngleBins * 1.4142135623730951)), kRayAngleBins - 1);
  const double w = u * bins.cos_j[j] - v * bins.sin_j[j], w2 = w * w;
  const double series =
      w * (1.0 +
           w2 * (1.0 / 6 +
                 w2 * (3.0 / 40 + w2 * (15.0 / 336 + w2 * (105.0 / 3456 + w2 * (945.0 / 42240))))));
  return bins.theta_j[j] + series;
}

// The angle in [0, pi / 2] of (cos, sin) = (cos_g, sin_g), both >= 0 and of unit length to
// rounding: what std::atan2(sin_g, cos_g) gives.
inline double ray_angle(double sin_g, double cos_g) {
  return sin_g <= cos_g ? ray_angle_below_45(sin_g, cos_g)
                        : 0.5 * kPi - ray_angle_below_45(cos_g, sin_g);
}

// The direction of the in-plane vector (x, y) in (-pi, pi]: std::atan2(y, x) to a few units in
// the last place, from the same table (the psi cells' vertex directions and circle crossings).
// (0, 0) gives 0; a negative zero y gives +pi where atan2 gives -pi (the same direction).
inline double direction_angle(double y, double x) {
  const double ax = std::abs(x), ay = std::abs(y);
  const double big = std::max(ax, ay);
  if (!(big > 0.0)) return 0.0;
  const double t = std::min(ax, ay) / big;  // tan of the angle to the nearer axis, <= 1
  const double c = 1.0 / std::sqrt(1.0 + t * t);
  const double below = ray_angle_below_45(t * c, c);
  const double a = ay <= ax ? below : 0.5 * kPi - below;  // in [0, pi / 2]
  const double q = x < 0.0 ? kPi - a : a;
  return y < 0.0 ? -q : q;
}

}  // namespace luxgrid::nearfield
