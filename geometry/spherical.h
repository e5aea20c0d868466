#pragma once
// Spherical-geometry kernels: solid angles and Lambert's projected solid angle of triangles and
// polygons seen from a point, robust for degenerate and large triangles (solid angles by the
// angle over the half turn, atan2's, never atan [VanOosterom1983]; the angles by the table angle
// of util/table_angle.h, atan2 to a few units in the last place without a library call). The
// near-field models (calc/nearfield) and reflected light (calc/indirect: form factors, the first
// bounce) share them.
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "util/robust_math.h"
#include "util/simd.h"
#include "util/table_angle.h"

namespace luxgrid::geometry {

// A Vec3 as the one-value V3 of the kernels below (util/simd.h), and four Vec3 as lanes.
inline simd::V3<double> v3(const Vec3& a) { return {a.x, a.y, a.z}; }
template <class F>
LUXGRID_LANE simd::V3<simd::D4> v3_lanes(const F& corner) {
  return {simd::make<simd::D4>([&](int l) { return corner(l).x; }),
          simd::make<simd::D4>([&](int l) { return corner(l).y; }),
          simd::make<simd::D4>([&](int l) { return corner(l).z; })};
}

// Solid angle (sr) of the triangle with corners a, b, c seen from the origin, given with their
// lengths la, lb, lc: Van Oosterom and Strackee (1983) [VanOosterom1983], Luksch et al. 2020
// Eq. 11,
//   tan(Omega / 2) = |a . (b x c)| / (la lb lc + (a . b) lc + (a . c) lb + (b . c) la),
// which for unit vectors is a . (b x c) / (1 + a.b + a.c + b.c): no corner needs normalising.
// The angle of the pair (denominator, numerator) over the half turn, as atan2 gives it, keeps
// Omega right above pi sr, where the denominator turns negative and plain atan would return
// Omega - 2 pi; a degenerate triangle (two equal vertices) gives 0. By the table angle
// (util/table_angle.h; the pair is of any length): this runs for every piece of the first
// bounce. Over T: one triangle or four (triangle_solid_angles_from4).
template <class T>
LUXGRID_LANE T triangle_solid_angle(const simd::V3<T>& a, const T& la, const simd::V3<T>& b,
                                    const T& lb, const simd::V3<T>& c, const T& lc) {
  const T numerator = simd::abs(simd::dot(a, simd::cross(b, c)));
  const T denominator =
      la * lb * lc + simd::dot(a, b) * lc + simd::dot(a, c) * lb + simd::dot(b, c) * la;
  return 2.0 * direction_angle(numerator, denominator);
}
inline double triangle_solid_angle(const Vec3& a, double la, const Vec3& b, double lb,
                                   const Vec3& c, double lc) {
  return triangle_solid_angle(v3(a), la, v3(b), lb, v3(c), lc);
}

// The same for unit vectors a, b, c (the spherical triangle).
inline double triangle_solid_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  return triangle_solid_angle(a, 1.0, b, 1.0, c, 1.0);
}

// One edge of Lambert's polygon formula (Lambert 1760; Baum et al. 1989) projected on the
// receiver normal n: theta n . g, where theta is the arc between the directions of a and b and
// g = (a x b) / |a x b|. The projected solid angle of a spherical polygon is
// |sum over edges| / 2. a and b are corners relative to the viewpoint, of any length (only their
// directions count), given with their inverse lengths inv_a = 1 / |a|, inv_b = 1 / |b|; equal
// directions give 0. theta = atan2(|a x b|, a . b) (accurate near 0 and pi, where acos(a . b) is
// not) by arc_angle, from the pair scaled to unit length, and 1 / |a x b| is taken beside it
// rather than after it: this runs for every edge of every exact form factor, where the library's
// atan2 and the divisions of normalising each corner and each angle took a sixth of a whole
// calculation.
//
// Over T in two steps, so that one edge and four (quad_projected_solid_angle) share them: the
// arc's terms, then the edge's value from the arc's angle (arc_angle's: the table's where
// is_unit_pair holds, std::atan2 elsewhere, which only one value takes).
template <class T>
struct LambertArc {
  simd::V3<T> c;  // a x b
  T length, s, cos,
      r2;  // |a x b|, the pair (sin, cos) of the arc scaled by inv_a inv_b, s^2 + cos^2
};
template <class T>
LUXGRID_LANE LambertArc<T> lambert_arc(const simd::V3<T>& a, const T& inv_a, const simd::V3<T>& b,
                                       const T& inv_b) {
  LambertArc<T> arc;
  arc.c = simd::cross(a, b);
  arc.length = simd::length(arc.c);
  const T scale = inv_a * inv_b;
  arc.s = arc.length * scale, arc.cos = simd::dot(a, b) * scale;
  arc.r2 = arc.s * arc.s + arc.cos * arc.cos;
  return arc;
}
// n . (a x b) theta / |a x b|; 0 for an edge of zero length.
template <class T>
LUXGRID_LANE T lambert_edge_value(const LambertArc<T>& arc, const T& theta, const simd::V3<T>& n) {
  return simd::select(arc.length > 0.0, simd::dot(n, arc.c) * (theta * (1.0 / arc.length)),
                      simd::splat<T>(0.0));
}
inline double lambert_edge(const Vec3& a, double inv_a, const Vec3& b, double inv_b,
                           const Vec3& n) {
  const LambertArc<double> arc = lambert_arc(v3(a), inv_a, v3(b), inv_b);
  if (!(arc.length > 0.0)) return 0.0;
  const double theta = is_unit_pair(arc.s, arc.r2) ? unit_pair_angle(arc.s, arc.cos, arc.r2)
                                                   : std::atan2(arc.s, arc.cos);
  return lambert_edge_value(arc, theta, v3(n));
}

// Projected solid angle (sr) of the spherical triangle a, b, c (unit vectors) for the receiver
// normal n: the integral of (w . n) over the triangle, exact (Lambert), for a triangle above the
// horizon.
inline double triangle_projected_solid_angle(const Vec3& a, const Vec3& b, const Vec3& c,
                                             const Vec3& n) {
  return 0.5 * std::abs(lambert_edge(a, 1.0, b, 1.0, n) + lambert_edge(b, 1.0, c, 1.0, n) +
                        lambert_edge(c, 1.0, a, 1.0, n));
}

// Solid angle (sr) of the planar triangle abc seen from s; 0 when s is a vertex. Over T: one
// triangle or four.
template <class T>
LUXGRID_LANE T triangle_solid_angle_from(const simd::V3<T>& s, const simd::V3<T>& a,
                                         const simd::V3<T>& b, const simd::V3<T>& c) {
  const simd::V3<T> ra = a - s, rb = b - s, rc = c - s;
  const T la = simd::length(ra), lb = simd::length(rb), lc = simd::length(rc);
  const simd::Mask<T> valid = simd::logical_and(simd::logical_and(la > 0.0, lb > 0.0), lc > 0.0);
  return simd::select(valid, triangle_solid_angle(ra, la, rb, lb, rc, lc), simd::splat<T>(0.0));
}
inline double triangle_solid_angle_from(const Vec3& s, const Vec3& a, const Vec3& b,
                                        const Vec3& c) {
  return triangle_solid_angle_from(v3(s), v3(a), v3(b), v3(c));
}

// Corners closer than this to the viewpoint are left out of projected_solid_angle: their edges
// subtend no defined angle, and (in the receiver's tangent plane after the horizon clip) they add
// nothing to the cosine-weighted integral.
inline constexpr double kMinCornerDistance_m = 1e-12;

// Projected solid angle (sr) of a planar polygon seen from the origin for the unit normal n, by
// Lambert's formula [Baum1989, Eq. 2]: |sum over edges lambert_edge(r_k, r_k+1)| / 2, with r_k
// the corners `rel[0..count)` (relative to the viewpoint). Exact for any planar polygon wholly
// above the viewpoint's horizon (clip it first: polygon3.h); bounded however close the viewpoint
// is (no singularity). In [0, pi].
inline double projected_solid_angle(const Vec3* rel, size_t count, const Vec3& n) {
  if (count < 3) return 0.0;
  double sum = 0.0;
  const Vec3 *prev = nullptr, *first = nullptr;
  double inv_prev = 0.0, inv_first = 0.0;
  for (size_t k = 0; k < count; ++k) {
    const double len = glm::length(rel[k]);
    if (!(len > kMinCornerDistance_m)) continue;
    const double inv = 1.0 / len;
    if (prev)
      sum += lambert_edge(*prev, inv_prev, rel[k], inv, n);
    else
      first = &rel[k], inv_first = inv;
    prev = &rel[k], inv_prev = inv;
  }
  if (!prev) return 0.0;
  sum += lambert_edge(*prev, inv_prev, *first, inv_first, n);
  return 0.5 * std::abs(sum);
}

}  // namespace luxgrid::geometry
