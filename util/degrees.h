#pragma once
// An angle in degrees as a project gives it, reduced to one turn before it is converted to
// radians. A rotation of 1e300 degrees is legal JSON; multiplied by pi / 180 first, its radians
// carry no information about where in the turn it lies (a double near 1e298 has no fractional
// digits, and pi / 180 is rounded), so an exact multiple of 360 turned the luminaire anywhere.
// std::fmod is exact for doubles (C++ [c.math.fmod], IEEE 754-2008 5.3.1 remainder: the result
// is the exact x - n y, always representable), so the reduction adds no rounding of its own.
#include <cmath>

namespace luxgrid {

inline constexpr double kDegreesPerTurn = 360.0;

// `deg` itself, bit for bit, when it lies within (-360, 360): every ordinary rotation keeps the
// bits it had, and so does every output computed from it. Beyond, its exact remainder modulo
// 360 (same sign as `deg`, in (-360, 360)); an exact multiple of 360 gives +0, the same as 0.
inline double reduce_degrees(double deg) {
  if (std::abs(deg) < kDegreesPerTurn) return deg;
  const double r = std::fmod(deg, kDegreesPerTurn);
  return r == 0.0 ? 0.0 : r;
}

}  // namespace luxgrid
