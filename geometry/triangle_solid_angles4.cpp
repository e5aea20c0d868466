#include "geometry/triangle_solid_angles4.h"

#include <cmath>

#include "geometry/table_angle_lanes.h"

namespace luxgrid::geometry {

using lanes::D4;
using lanes::kSignBit;
using lanes::L4;

[[gnu::target_clones("avx2", "default")]] void triangle_solid_angles_from4(
    const Vec3& s, const Vec3 (&a)[4], const Vec3 (&b)[4], const Vec3 (&c)[4], double (&out)[4]) {
  // The corners relative to s (triangle_solid_angle_from: ra = a - s, ...).
  const D4 ax = {a[0].x - s.x, a[1].x - s.x, a[2].x - s.x, a[3].x - s.x};
  const D4 ay = {a[0].y - s.y, a[1].y - s.y, a[2].y - s.y, a[3].y - s.y};
  const D4 az = {a[0].z - s.z, a[1].z - s.z, a[2].z - s.z, a[3].z - s.z};
  const D4 bx = {b[0].x - s.x, b[1].x - s.x, b[2].x - s.x, b[3].x - s.x};
  const D4 by = {b[0].y - s.y, b[1].y - s.y, b[2].y - s.y, b[3].y - s.y};
  const D4 bz = {b[0].z - s.z, b[1].z - s.z, b[2].z - s.z, b[3].z - s.z};
  const D4 cx = {c[0].x - s.x, c[1].x - s.x, c[2].x - s.x, c[3].x - s.x};
  const D4 cy = {c[0].y - s.y, c[1].y - s.y, c[2].y - s.y, c[3].y - s.y};
  const D4 cz = {c[0].z - s.z, c[1].z - s.z, c[2].z - s.z, c[3].z - s.z};
  // Their lengths as glm::length: sqrt((x x + y y) + z z).
  const D4 la2 = (ax * ax + ay * ay) + az * az, lb2 = (bx * bx + by * by) + bz * bz,
           lc2 = (cx * cx + cy * cy) + cz * cz;
  const D4 la = {std::sqrt(la2[0]), std::sqrt(la2[1]), std::sqrt(la2[2]), std::sqrt(la2[3])};
  const D4 lb = {std::sqrt(lb2[0]), std::sqrt(lb2[1]), std::sqrt(lb2[2]), std::sqrt(lb2[3])};
  const D4 lc = {std::sqrt(lc2[0]), std::sqrt(lc2[1]), std::sqrt(lc2[2]), std::sqrt(lc2[3])};
  const L4 valid = (la > 0.0) & (lb > 0.0) & (lc > 0.0);
  // triangle_solid_angle: |a . (b x c)| over la lb lc + (a . b) lc + (a . c) lb + (b . c) la.
  const D4 kx = by * cz - cy * bz, ky = bz * cx - cz * bx, kz = bx * cy - cx * by;
  const D4 numerator = (D4)((L4)((ax * kx + ay * ky) + az * kz) & ~kSignBit);
  const D4 ab = (ax * bx + ay * by) + az * bz, ac = (ax * cx + ay * cy) + az * cz,
           bc = (bx * cx + by * cy) + bz * cz;
  const D4 denominator = ((la * lb * lc + ab * lc) + ac * lb) + bc * la;
  // direction_angle(numerator, denominator): numerator >= 0, so only the sign of the
  // denominator picks the half turn.
  const D4 ax_ = (D4)((L4)denominator & ~kSignBit), ay_ = numerator;
  const D4 big = ax_ < ay_ ? ay_ : ax_;    // std::max(ax, ay)
  const D4 small = ay_ < ax_ ? ay_ : ax_;  // std::min(ax, ay)
  const L4 some = big > 0.0;
  const D4 t = small / big;
  const D4 one_t2 = 1.0 + t * t;
  const D4 root = {std::sqrt(one_t2[0]), std::sqrt(one_t2[1]), std::sqrt(one_t2[2]),
                   std::sqrt(one_t2[3])};
  const D4 cosine = 1.0 / root;
  const D4 one = {1.0, 1.0, 1.0, 1.0};
  const L4 flat = ay_ <= ax_;
  const D4 qs = (flat ? t : one) * cosine, qc = (flat ? one : t) * cosine;
  // quadrant_angle(qs, qc) = octant_table_angle(qs, qc, false, 1.0).
  const L4 front = {0, 0, 0, 0};
  D4 angle;
  lanes::octant_table_angle(qs, qc, front, one, angle);
  const D4 q = denominator < 0.0 ? kPi - angle : angle;
  const D4 omega = 2.0 * q;
  for (int k = 0; k < 4; ++k) out[k] = valid[k] && some[k] ? omega[k] : 0.0;
}

}  // namespace luxgrid::geometry
