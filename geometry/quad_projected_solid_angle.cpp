#include "geometry/quad_projected_solid_angle.h"

#include "geometry/spherical.h"
#include "util/simd.h"

namespace luxgrid::geometry {

namespace {

// projected_solid_angle(rel, 4, n) with lane k the edge from corner k (a) to corner k + 1 (b),
// the last back to corner 0: lambert_arc and lambert_edge_value over four lanes, the edges added
// in the scalar loop's order.
LUXGRID_LANE double quad_kernel(const Vec3* rel, const Vec3& n) {
  using simd::D4;
  const simd::V3<D4> a = v3_lanes([rel](int l) { return rel[l]; });
  const simd::V3<D4> b = v3_lanes([rel](int l) { return rel[(l + 1) % 4]; });
  const D4 len = simd::length(a);  // glm::length, as projected_solid_angle takes it
  if (!simd::all(len > kMinCornerDistance_m)) return projected_solid_angle(rel, 4, n);
  const D4 inv_a = 1.0 / len;
  const D4 inv_b = {inv_a[1], inv_a[2], inv_a[3], inv_a[0]};
  const LambertArc<D4> arc = lambert_arc(a, inv_a, b, inv_b);
  // arc_angle: a pair off unit length or a negative sine (-0 too) goes to std::atan2, the
  // scalar code's branch; an edge of zero length adds 0 (lambert_edge's first return).
  if (!simd::all(
          simd::logical_or(is_unit_pair(arc.s, arc.r2), simd::logical_not(arc.length > 0.0))))
    return projected_solid_angle(rel, 4, n);
  const D4 edge = lambert_edge_value(
      arc, unit_pair_angle(arc.s, arc.cos, arc.r2),
      simd::V3<D4>{simd::splat<D4>(n.x), simd::splat<D4>(n.y), simd::splat<D4>(n.z)});
  return 0.5 * std::abs(simd::sum_in_order(edge));
}

}  // namespace

LUXGRID_MULTIVERSION(double, quad_projected_solid_angle, (const Vec3* rel, const Vec3& n), (rel, n),
                     quad_kernel)

}  // namespace luxgrid::geometry
