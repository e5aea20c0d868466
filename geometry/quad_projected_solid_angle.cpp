#include "geometry/quad_projected_solid_angle.h"

#include <cmath>

#include "geometry/spherical.h"
#include "geometry/table_angle_lanes.h"

namespace luxgrid::geometry {

using lanes::D4;
using lanes::kSignBit;
using lanes::L4;

[[gnu::target_clones("avx2", "default")]] double quad_projected_solid_angle(const Vec3* rel,
                                                                            const Vec3& n) {
  // Lane k is the edge from corner k (a) to corner k + 1 (b), the last back to corner 0.
  const D4 ax = {rel[0].x, rel[1].x, rel[2].x, rel[3].x};
  const D4 ay = {rel[0].y, rel[1].y, rel[2].y, rel[3].y};
  const D4 az = {rel[0].z, rel[1].z, rel[2].z, rel[3].z};
  const D4 bx = {rel[1].x, rel[2].x, rel[3].x, rel[0].x};
  const D4 by = {rel[1].y, rel[2].y, rel[3].y, rel[0].y};
  const D4 bz = {rel[1].z, rel[2].z, rel[3].z, rel[0].z};
  // |a| as glm::length: sqrt((x x + y y) + z z).
  const D4 len2 = (ax * ax + ay * ay) + az * az;
  const D4 len = {std::sqrt(len2[0]), std::sqrt(len2[1]), std::sqrt(len2[2]), std::sqrt(len2[3])};
  if (!lanes::all(len > kMinCornerDistance_m)) return projected_solid_angle(rel, 4, n);
  const D4 inv_a = 1.0 / len;
  const D4 inv_b = {inv_a[1], inv_a[2], inv_a[3], inv_a[0]};
  // lambert_edge: c = a x b (glm::cross), its length, the pair scaled to unit length.
  const D4 cx = ay * bz - by * az, cy = az * bx - bz * ax, cz = ax * by - bx * ay;
  const D4 clen2 = (cx * cx + cy * cy) + cz * cz;
  const D4 clen = {std::sqrt(clen2[0]), std::sqrt(clen2[1]), std::sqrt(clen2[2]),
                   std::sqrt(clen2[3])};
  const D4 scale = inv_a * inv_b;
  const D4 s = clen * scale, c = ((ax * bx + ay * by) + az * bz) * scale;
  // arc_angle: a pair off unit length or a negative sine (-0 too) goes to std::atan2, the
  // scalar code's branch; an edge of zero length adds 0 (lambert_edge's first return).
  const D4 r2 = s * s + c * c;
  const L4 has_length = clen > 0.0;
  const L4 unit = (D4)((L4)(r2 - 1.0) & ~kSignBit) <= kUnitPairTolerance;
  const L4 s_positive = ((L4)s & kSignBit) == 0;
  if (!lanes::all((unit & s_positive) | ~has_length)) return projected_solid_angle(rel, 4, n);
  // octant_table_angle(s, |c|, c < 0, 1.5 - 0.5 r2).
  const D4 cabs = (D4)((L4)c & ~kSignBit);
  D4 angle;
  lanes::octant_table_angle(s, cabs, c < 0.0, 1.5 - 0.5 * r2, angle);
  // glm::dot(n, c) x (angle x (1 / |c|)); 0 for an edge of zero length.
  const D4 zero = {0.0, 0.0, 0.0, 0.0};
  const D4 edge = has_length ? ((n.x * cx + n.y * cy) + n.z * cz) * (angle * (1.0 / clen)) : zero;
  double sum = 0.0;
  for (int k = 0; k < 4; ++k) sum += edge[k];
  return 0.5 * std::abs(sum);
}

}  // namespace luxgrid::geometry
