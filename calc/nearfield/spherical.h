#pragma once
// Spherical-geometry kernels of the near-field models, robust for degenerate and large
// triangles (solid angles by atan2, never atan [VanOosterom1983]).
#include <cmath>

#include "util/robust_math.h"

namespace luxgrid::nearfield {

// Solid angle (sr) of the spherical triangle with unit vertices a, b, c: Van Oosterom and
// Strackee (1983), Luksch et al. 2020 Eq. 11,
//   tan(Omega / 2) = a . (b x c) / (1 + a.b + a.c + b.c).
// atan2 keeps Omega right above pi sr, where the denominator turns negative and plain atan
// would return Omega - 2 pi; a degenerate triangle (two equal vertices) gives 0.
inline double triangle_solid_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double numerator = std::abs(glm::dot(a, glm::cross(b, c)));
  const double denominator = 1.0 + glm::dot(a, b) + glm::dot(a, c) + glm::dot(b, c);
  return 2.0 * std::atan2(numerator, denominator);
}

// One edge of Lambert's polygon formula (Lambert 1760; Baum et al. 1989): theta * g, where
// theta is the arc from unit vector a to unit vector b and g = (a x b) / |a x b|. The projected
// solid angle of a spherical polygon is |n . sum over edges| / 2. Equal vertices give 0.
inline Vec3 lambert_edge(const Vec3& a, const Vec3& b) {
  const Vec3 c = glm::cross(a, b);
  const double s = glm::length(c);
  if (!(s > 0.0)) return Vec3(0.0);
  return c * (std::atan2(s, glm::dot(a, b)) / s);
}

// Projected solid angle (sr) of the spherical triangle a, b, c for the receiver normal n:
// the integral of (w . n) over the triangle, exact (Lambert), for a triangle above the horizon.
inline double triangle_projected_solid_angle(const Vec3& a, const Vec3& b, const Vec3& c,
                                             const Vec3& n) {
  return 0.5 * std::abs(glm::dot(n, lambert_edge(a, b) + lambert_edge(b, c) + lambert_edge(c, a)));
}

}  // namespace luxgrid::nearfield
