#include "geometry/quad_projected_solid_angle.h"

#include <cmath>

#include "geometry/spherical.h"
#include "util/table_angle.h"

namespace luxgrid::geometry {

namespace {
// Four doubles, one per edge: GCC's vector extension, four lanes of AVX2 in the avx2 build and
// two SSE2 pairs in the default one; each operation is the IEEE operation of every lane.
using D4 = double __attribute__((vector_size(32)));
using L4 = long long __attribute__((vector_size(32)));

bool all(const L4& mask) { return mask[0] && mask[1] && mask[2] && mask[3]; }
// The sign bit of a double (a vector cast reinterprets the bits).
constexpr long long kSignBit = static_cast<long long>(0x8000000000000000ULL);
}  // namespace

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
  if (!all(len > kMinCornerDistance_m)) return projected_solid_angle(rel, 4, n);
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
  if (!all((unit & s_positive) | ~has_length)) return projected_solid_angle(rel, 4, n);
  // octant_table_angle(s, |c|, c < 0, 1.5 - 0.5 r2), lane by lane the same operations: the
  // octant's base and sign as its tables give them, selected without branches.
  const D4 cabs = (D4)((L4)c & ~kSignBit);
  const D4 u = cabs < s ? cabs : s;  // std::min(s, cabs)
  const D4 v = s < cabs ? cabs : s;  // std::max(s, cabs)
  const L4 steep = s > cabs, back = c < 0.0;
  const D4 half_pi = {0.5 * kPi, 0.5 * kPi, 0.5 * kPi, 0.5 * kPi};
  const D4 pi_or_0 = back ? D4{kPi, kPi, kPi, kPi} : D4{0.0, 0.0, 0.0, 0.0};
  const D4 base = steep ? half_pi : pi_or_0;
  const D4 one = {1.0, 1.0, 1.0, 1.0};
  const L4 negative = steep ^ back;  // kSign: -1 for octants 1 and 2
  const D4 sign = negative ? -one : one;
  const D4 bins = u * (kAngleTableBins * 1.4142135623730951);
  D4 row_sin, row_cos, row_angle;
  for (int k = 0; k < 4; ++k) {
    // A lane whose value is not used (NaN there) reads row 0 rather than converting NaN.
    const int j = bins[k] >= 0.0 ? std::min(static_cast<int>(bins[k]), kAngleTableBins - 1) : 0;
    row_sin[k] = kAngleTable[j].sin, row_cos[k] = kAngleTable[j].cos;
    row_angle[k] = kAngleTable[j].angle;
  }
  const D4 w = (1.5 - 0.5 * r2) * (u * row_cos - v * row_sin), w2 = w * w, w4 = w2 * w2,
           w8 = w4 * w4;
  const D4 series = w * ((1.0 + w2 * (1.0 / 6)) + w4 * (3.0 / 40 + w2 * (15.0 / 336)) +
                         w8 * (105.0 / 3456 + w2 * (945.0 / 42240)));
  const D4 angle = base + sign * (row_angle + series);
  // glm::dot(n, c) x (angle x (1 / |c|)); 0 for an edge of zero length.
  const D4 zero = {0.0, 0.0, 0.0, 0.0};
  const D4 edge = has_length ? ((n.x * cx + n.y * cy) + n.z * cz) * (angle * (1.0 / clen)) : zero;
  double sum = 0.0;
  for (int k = 0; k < 4; ++k) sum += edge[k];
  return 0.5 * std::abs(sum);
}

}  // namespace luxgrid::geometry
