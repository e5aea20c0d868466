#pragma once
// Four doubles as the lanes of one computation (GCC's vector extension: one AVX2 register in a
// function built for AVX2 by target_clones, two SSE2 ones in its default build), and
// util/table_angle.h's octant_table_angle on them: each lane the same IEEE operations as the
// scalar code, in the same order, so the same bits. Used by luxgrid's four-at-once kernels
// (geometry/quad_projected_solid_angle, geometry/triangle_solid_angles4, the radiosity sweep's
// row sums, the table rung's ray ends).
#include <algorithm>

#include "util/table_angle.h"

namespace luxgrid::geometry::lanes {

using D4 = double __attribute__((vector_size(32)));
using L4 = long long __attribute__((vector_size(32)));  // lane masks: -1 true, 0 false

// The sign bit of a double (a vector cast reinterprets a lane's bits).
inline constexpr long long kSignBit = static_cast<long long>(0x8000000000000000ULL);

inline bool all(const L4& mask) { return mask[0] && mask[1] && mask[2] && mask[3]; }

// octant_table_angle(s, c, back, k) lane by lane, the octant's base and sign as its tables give
// them, selected without branches. Vectors by reference and the body inlined: a vector by value
// would change the function's calling convention between the two builds of its callers.
[[gnu::always_inline]] inline void octant_table_angle(const D4& s, const D4& c, const L4& back,
                                                      const D4& k, D4& angle) {
  const D4 u = c < s ? c : s;  // std::min(s, c)
  const D4 v = s < c ? c : s;  // std::max(s, c)
  const L4 steep = s > c;
  const D4 zero = {0.0, 0.0, 0.0, 0.0}, one = {1.0, 1.0, 1.0, 1.0};
  const D4 half_pi = {0.5 * kPi, 0.5 * kPi, 0.5 * kPi, 0.5 * kPi};
  const D4 pi = {kPi, kPi, kPi, kPi};
  const D4 base = steep ? half_pi : (back ? pi : zero);  // kBase {0, pi, pi / 2, pi / 2}
  const D4 sign = (steep ^ back) ? -one : one;           // kSign {1, -1, -1, 1}
  const D4 bins = u * (kAngleTableBins * 1.4142135623730951);
  D4 row_sin, row_cos, row_angle;
  for (int l = 0; l < 4; ++l) {
    // A lane whose value is not used (NaN there) reads row 0 rather than converting NaN.
    const int j = bins[l] >= 0.0 ? std::min(static_cast<int>(bins[l]), kAngleTableBins - 1) : 0;
    row_sin[l] = kAngleTable[j].sin, row_cos[l] = kAngleTable[j].cos;
    row_angle[l] = kAngleTable[j].angle;
  }
  const D4 w = k * (u * row_cos - v * row_sin), w2 = w * w, w4 = w2 * w2, w8 = w4 * w4;
  const D4 series = w * ((1.0 + w2 * (1.0 / 6)) + w4 * (3.0 / 40 + w2 * (15.0 / 336)) +
                         w8 * (105.0 / 3456 + w2 * (945.0 / 42240)));
  angle = base + sign * (row_angle + series);
}

}  // namespace luxgrid::geometry::lanes
