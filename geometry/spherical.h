#pragma once
// Spherical-geometry kernels: solid angles and Lambert's projected solid angle of triangles and
// polygons seen from a point, robust for degenerate and large triangles (solid angles by atan2,
// never atan [VanOosterom1983]). The near-field models (calc/nearfield) and reflected light
// (calc/indirect: form factors, the first bounce) share them.
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "util/robust_math.h"

namespace luxgrid::geometry {

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

// Solid angle (sr) of the planar triangle abc seen from s (triangle_solid_angle of the unit
// directions); 0 when s is a vertex.
inline double triangle_solid_angle_from(const Vec3& s, const Vec3& a, const Vec3& b,
                                        const Vec3& c) {
  const Vec3 ra = a - s, rb = b - s, rc = c - s;
  const double la = glm::length(ra), lb = glm::length(rb), lc = glm::length(rc);
  if (!(la > 0.0 && lb > 0.0 && lc > 0.0)) return 0.0;
  return triangle_solid_angle(ra / la, rb / lb, rc / lc);
}

// Corners closer than this to the viewpoint are left out of projected_solid_angle: their edges
// subtend no defined angle, and (in the receiver's tangent plane after the horizon clip) they add
// nothing to the cosine-weighted integral.
inline constexpr double kMinCornerDistance_m = 1e-12;

// Projected solid angle (sr) of a planar polygon seen from the origin for the unit normal n, by
// Lambert's formula [Baum1989, Eq. 2]: |n . sum over edges lambert_edge(u_k, u_k+1)| / 2, with
// u_k the unit directions to the corners `rel[0..count)` (relative to the viewpoint). Exact for
// any planar polygon wholly above the viewpoint's horizon (clip it first: polygon3.h); bounded
// however close the viewpoint is (no singularity). In [0, pi].
inline double projected_solid_angle(const Vec3* rel, size_t count, const Vec3& n) {
  if (count < 3) return 0.0;
  Vec3 sum(0.0), prev(0.0), first(0.0);
  bool have_prev = false;
  for (size_t k = 0; k < count; ++k) {
    const double len = glm::length(rel[k]);
    if (!(len > kMinCornerDistance_m)) continue;
    const Vec3 u = rel[k] / len;
    if (have_prev)
      sum += lambert_edge(prev, u);
    else
      first = u;
    prev = u;
    have_prev = true;
  }
  if (!have_prev) return 0.0;
  sum += lambert_edge(prev, first);
  return 0.5 * std::abs(glm::dot(n, sum));
}

}  // namespace luxgrid::geometry
