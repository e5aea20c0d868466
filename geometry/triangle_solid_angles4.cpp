#include "geometry/triangle_solid_angles4.h"

#include <cmath>

#include "util/table_angle.h"

namespace luxgrid::geometry {

namespace {
// Four doubles, one per triangle (GCC's vector extension: one AVX2 register or two SSE2 ones);
// every operation is the IEEE operation of each lane.
using D4 = double __attribute__((vector_size(32)));
using L4 = long long __attribute__((vector_size(32)));
constexpr long long kSignBit = static_cast<long long>(0x8000000000000000ULL);
}  // namespace

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
  // quadrant_angle(qs, qc) = octant_table_angle(qs, qc, false): octant 0 or 2.
  const D4 u = qc < qs ? qc : qs;  // std::min(qs, qc)
  const D4 v = qs < qc ? qc : qs;  // std::max(qs, qc)
  const L4 steep = qs > qc;
  const D4 bins = u * (kAngleTableBins * 1.4142135623730951);
  D4 row_sin, row_cos, row_angle;
  for (int k = 0; k < 4; ++k) {
    // A lane whose value is not used (NaN there) reads row 0 rather than converting NaN.
    const int j = bins[k] >= 0.0 ? std::min(static_cast<int>(bins[k]), kAngleTableBins - 1) : 0;
    row_sin[k] = kAngleTable[j].sin, row_cos[k] = kAngleTable[j].cos;
    row_angle[k] = kAngleTable[j].angle;
  }
  const D4 w = 1.0 * (u * row_cos - v * row_sin), w2 = w * w, w4 = w2 * w2, w8 = w4 * w4;
  const D4 series = w * ((1.0 + w2 * (1.0 / 6)) + w4 * (3.0 / 40 + w2 * (15.0 / 336)) +
                         w8 * (105.0 / 3456 + w2 * (945.0 / 42240)));
  const D4 zero = {0.0, 0.0, 0.0, 0.0};
  const D4 half_pi = {0.5 * kPi, 0.5 * kPi, 0.5 * kPi, 0.5 * kPi};
  const D4 base = steep ? half_pi : zero;
  const D4 sign = steep ? -one : one;
  const D4 angle = base + sign * (row_angle + series);
  const D4 q = denominator < 0.0 ? kPi - angle : angle;
  const D4 omega = 2.0 * q;
  for (int k = 0; k < 4; ++k) out[k] = valid[k] && some[k] ? omega[k] : 0.0;
}

}  // namespace luxgrid::geometry
