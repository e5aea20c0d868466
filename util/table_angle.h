#pragma once
// Angles from a sine and a cosine without atan2 and without a division: a table of 64 unit
// vectors and the arcsine's series. The library's atan2 was a quarter of the near field's table
// rung (docs/nearfield.md) and an eighth of a whole office calculation, most of it in Lambert's
// polygon formula (geometry/spherical.h, docs/indirect.md); both now take their angles here, and
// so does the intensity table's look-up (photometry/tabular_distribution.cpp).
//
// Reduction: with u = min(sin, cos) (angles up to 45 degrees; beyond, pi / 2 minus the angle of
// the swapped pair, and pi minus either for a negative cosine), the bin
// j = floor(kAngleTableBins sqrt(2) u) has a stored unit vector (s_j, c_j) at angle theta_j, and
// by the subtraction formula
//   angle = theta_j + asin(w),  w = sin(angle - theta_j) = u c_j - v s_j  (v the other one).
// d angle / d u = 1 / cos <= sqrt(2) up to 45 degrees, so a bin spans at most 1 / kAngleTableBins
// rad and |w| < 0.016; asin(w) is its Taylor series (octant_table_angle). No division, no branch
// and no library call. The results agree with std::atan2 to a few units in the last place
// (tests/util/table_angle_test.cpp).
#include <algorithm>
#include <array>
#include <cmath>

#include "util/robust_math.h"
#include "util/simd.h"

namespace luxgrid {

inline constexpr int kAngleTableBins = 64;

struct AngleTableRow {
  double sin, cos, angle;
};

// Row j: sin = j / (64 sqrt(2)), cos = sqrt(1 - sin^2), angle = std::atan2(sin, cos), each as
// the double those expressions give (written out so that the table is a constant: no start-up
// code, nothing to go wrong if an angle is asked for while other globals are built;
// TableAngle.TableIsWhatItsFormulaGives recomputes it).
inline constexpr std::array<AngleTableRow, kAngleTableBins> kAngleTable = {{
    {0x0p+0, 0x1p+0, 0x0p+0},                                            // 0
    {0x1.6a09e667f3bccp-7, 0x1.fff7ffefffcp-1, 0x1.6a0bc9269b862p-7},    // 1
    {0x1.6a09e667f3bccp-6, 0x1.ffdffeffeffecp-1, 0x1.6a1171b40fe3ep-6},  // 2
    {0x1.0f876ccdf6cd9p-5, 0x1.ffb7faef499ffp-1, 0x1.0f9428c3b8061p-5},  // 3
    {0x1.6a09e667f3bccp-5, 0x1.ff7feffbfebf9p-1, 0x1.6a2818b1a0bd7p-5},  // 4
    {0x1.c48c6001f0abfp-5, 0x1.ff37d8e0b6489p-1, 0x1.c4c761b4ba9a9p-5},  // 5
    {0x1.0f876ccdf6cd9p-4, 0x1.fedfaed24fdd7p-1, 0x1.0fba7009d4b6bp-4},  // 6
    {0x1.3cc8a99af5453p-4, 0x1.fe77697cad553p-1, 0x1.3d19ba0e702c9p-4},  // 7
    {0x1.6a09e667f3bccp-4, 0x1.fdfefefebe3d6p-1, 0x1.6a83017dfb54dp-4},  // 8
    {0x1.974b2334f2346p-4, 0x1.fd7663e5c8f94p-1, 0x1.97f7bbc96dd28p-4},  // 9
    {0x1.c48c6001f0abfp-4, 0x1.fcdd8b27ec33ep-1, 0x1.c57961abcecd9p-4},  // 10
    {0x1.f1cd9cceef239p-4, 0x1.fc34661dd26e9p-1, 0x1.f3096f9bbfda7p-4},  // 11
    {0x1.0f876ccdf6cd9p-3, 0x1.fb7ae47b907cbp-1, 0x1.1054b320089f2p-3},  // 12
    {0x1.26280b3476096p-3, 0x1.fab0f448a6b43p-1, 0x1.272d6573e33b5p-3},  // 13
    {0x1.3cc8a99af5453p-3, 0x1.f9d681d71b812p-1, 0x1.3e0f9402fbc5fp-3},  // 14
    {0x1.536948017480fp-3, 0x1.f8eb77b9a4decp-1, 0x1.54fc06d9010b5p-3},  // 15
    {0x1.6a09e667f3bccp-3, 0x1.f7efbeb8d4f12p-1, 0x1.6bf3891642141p-3},  // 16
    {0x1.80aa84ce72f89p-3, 0x1.f6e33dc73c9fap-1, 0x1.82f6e934d1b4fp-3},  // 17
    {0x1.974b2334f2346p-3, 0x1.f5c5d9f475935p-1, 0x1.9a06f95095ffp-3},   // 18
    {0x1.adebc19b71702p-3, 0x1.f497765f035fdp-1, 0x1.b1248f728e7d7p-3},  // 19
    {0x1.c48c6001f0abfp-3, 0x1.f357f424f9d9fp-1, 0x1.c85085dfa1f6p-3},   // 20
    {0x1.db2cfe686fe7cp-3, 0x1.f207325354b42p-1, 0x1.df8bbb6b4ad8dp-3},  // 21
    {0x1.f1cd9cceef239p-3, 0x1.f0a50dd3ea57fp-1, 0x1.f6d713ce80cf3p-3},  // 22
    {0x1.04371d9ab72fbp-2, 0x1.ef316159e1a28p-1, 0x1.0719bc01a2f76p-2},  // 23
    {0x1.0f876ccdf6cd9p-2, 0x1.edac054c8f94cp-1, 0x1.12d0eb52a397fp-2},  // 24
    {0x1.1ad7bc01366b7p-2, 0x1.ec14cfb09f31fp-1, 0x1.1e91922c04f4ep-2},  // 25
    {0x1.26280b3476096p-2, 0x1.ea6b940f629d3p-1, 0x1.2a5c2e1995beap-2},  // 26
    {0x1.31785a67b5a74p-2, 0x1.e8b0235c29059p-1, 0x1.3631401aa28d5p-2},  // 27
    {0x1.3cc8a99af5453p-2, 0x1.e6e24bd771067p-1, 0x1.42114cdf09f1ap-2},  // 28
    {0x1.4818f8ce34e31p-2, 0x1.e501d8efcac41p-1, 0x1.4dfcdd084ae16p-2},  // 29
    {0x1.536948017480fp-2, 0x1.e30e932038295p-1, 0x1.59f47d6eeec02p-2},  // 30
    {0x1.5eb99734b41eep-2, 0x1.e1083fcbd4302p-1, 0x1.65f8bf6cba766p-2},  // 31
    {0x1.6a09e667f3bccp-2, 0x1.deeea11683f49p-1, 0x1.720a392c1d954p-2},  // 32
    {0x1.755a359b335abp-2, 0x1.dcc175ba6d61ap-1, 0x1.7e2985fd638a4p-2},  // 33
    {0x1.80aa84ce72f89p-2, 0x1.da8078d9e7703p-1, 0x1.8a5746b239a9dp-2},  // 34
    {0x1.8bfad401b2967p-2, 0x1.d82b61cd8f129p-1, 0x1.969422002d973p-2},  // 35
    {0x1.974b2334f2346p-2, 0x1.d5c1e3ee21d7dp-1, 0x1.a2e0c4eada98fp-2},  // 36
    {0x1.a29b726831d24p-2, 0x1.d343ae59b3e2ep-1, 0x1.af3de336921bcp-2},  // 37
    {0x1.adebc19b71702p-2, 0x1.d0b06bb3c9c99p-1, 0x1.bbac37e464699p-2},  // 38
    {0x1.b93c10ceb10e1p-2, 0x1.ce07c1dfd00d2p-1, 0x1.c82c85b88aef4p-2},  // 39
    {0x1.c48c6001f0abfp-2, 0x1.cb4951b558d17p-1, 0x1.d4bf97cc55efdp-2},  // 40
    {0x1.cfdcaf353049ep-2, 0x1.c874b6ad74e5ep-1, 0x1.e166422ce4e3fp-2},  // 41
    {0x1.db2cfe686fe7cp-2, 0x1.c589868866a82p-1, 0x1.ee2162881bdacp-2},  // 42
    {0x1.e67d4d9baf85ap-2, 0x1.c28750ead345ep-1, 0x1.faf1e0e97a028p-2},  // 43
    {0x1.f1cd9cceef239p-2, 0x1.bf6d9ef178c08p-1, 0x1.03ec5844579e2p-1},  // 44
    {0x1.fd1dec022ec17p-2, 0x1.bc3bf2ba4c1a9p-1, 0x1.0a6b685608dfep-1},  // 45
    {0x1.04371d9ab72fbp-1, 0x1.b8f1c6e1ba53p-1, 0x1.10f6a6d0b18f1p-1},   // 46
    {0x1.09df453456feap-1, 0x1.b58e8df297306p-1, 0x1.178ea0e7d7c31p-1},  // 47
    {0x1.0f876ccdf6cd9p-1, 0x1.b211b1c70d023p-1, 0x1.1e33eb72bed7p-1},   // 48
    {0x1.152f9467969c8p-1, 0x1.ae7a92d89ebffp-1, 0x1.24e723938233dp-1},  // 49
    {0x1.1ad7bc01366b7p-1, 0x1.aac8877d004b5p-1, 0x1.2ba8ef7058485p-1},  // 50
    {0x1.207fe39ad63a7p-1, 0x1.a6fadb0d2c899p-1, 0x1.3279ff017bdc8p-1},  // 51
    {0x1.26280b3476096p-1, 0x1.a310ccf3b376p-1, 0x1.395b0cf6a3bb9p-1},   // 52
    {0x1.2bd032ce15d85p-1, 0x1.9f098f9eb74acp-1, 0x1.404cdfb76f509p-1},  // 53
    {0x1.31785a67b5a74p-1, 0x1.9ae447517297ap-1, 0x1.47504a82c6f0ap-1},  // 54
    {0x1.3720820155763p-1, 0x1.96a008d063609p-1, 0x1.4e662eb1e6405p-1},  // 55
    {0x1.3cc8a99af5453p-1, 0x1.923bd7e25164dp-1, 0x1.558f7d24a5ef2p-1},  // 56
    {0x1.4270d13495142p-1, 0x1.8db6a59f4d7d7p-1, 0x1.5ccd37dda9bb4p-1},  // 57
    {0x1.4818f8ce34e31p-1, 0x1.890f4e8570c86p-1, 0x1.642073d664c58p-1},  // 58
    {0x1.4dc12067d4b2p-1, 0x1.844498497b811p-1, 0x1.6b8a5b1480ea8p-1},   // 59
    {0x1.536948017480fp-1, 0x1.7f552f5767565p-1, 0x1.730c2f0c3345ep-1},  // 60
    {0x1.59116f9b144ffp-1, 0x1.7a3fa3f4735cdp-1, 0x1.7aa74b5d83f22p-1},  // 61
    {0x1.5eb99734b41eep-1, 0x1.750266f0facc4p-1, 0x1.825d28fdae66cp-1},  // 62
    {0x1.6461bece53eddp-1, 0x1.6f9bc5d45947ap-1, 0x1.8a2f61e1b3b5dp-1},  // 63
}};

// The table's rows j = floor(bins) (at most the last) for one value or for lanes (T = double or
// simd::D4): each lane reads its own row. A value whose angle is not used (NaN: a pair the caller
// does not select) reads row 0 rather than converting NaN.
LUXGRID_LANE void angle_table_rows(double bins, double& row_sin, double& row_cos,
                                   double& row_angle) {
  const int j = bins >= 0.0 ? std::min(static_cast<int>(bins), kAngleTableBins - 1) : 0;
  row_sin = kAngleTable[j].sin, row_cos = kAngleTable[j].cos, row_angle = kAngleTable[j].angle;
}
LUXGRID_LANE void angle_table_rows(const simd::D4& bins, simd::D4& row_sin, simd::D4& row_cos,
                                   simd::D4& row_angle) {
  for (int l = 0; l < simd::kLanes; ++l) {
    const int j = bins[l] >= 0.0 ? std::min(static_cast<int>(bins[l]), kAngleTableBins - 1) : 0;
    row_sin[l] = kAngleTable[j].sin, row_cos[l] = kAngleTable[j].cos;
    row_angle[l] = kAngleTable[j].angle;
  }
}

// The octant's base angle and sign (steep: s > c; back: a negative cosine): {0, pi, pi / 2,
// pi / 2} and {1, -1, -1, 1} by octant 2 steep + back. One value reads them from a table, so
// there is no branch: in Lambert's formula the octants are equally likely, and a mispredicted
// branch costs as much as the rest; lanes select them.
LUXGRID_LANE void octant_base_sign(bool steep, bool back, double& base, double& sign) {
  static constexpr double kBase[4] = {0.0, kPi, 0.5 * kPi, 0.5 * kPi};
  static constexpr double kSign[4] = {1.0, -1.0, -1.0, 1.0};
  const int octant = 2 * steep + back;
  base = kBase[octant], sign = kSign[octant];
}
LUXGRID_LANE void octant_base_sign(const simd::L4& steep, const simd::L4& back, simd::D4& base,
                                   simd::D4& sign) {
  const simd::D4 zero = simd::splat<simd::D4>(0.0), one = simd::splat<simd::D4>(1.0);
  base = steep ? simd::splat<simd::D4>(0.5 * kPi) : (back ? simd::splat<simd::D4>(kPi) : zero);
  sign = (steep ^ back) ? -one : one;
}

// asin(w) / w - 1 = w^2 / 6 + 3 w^4 / 40 + ... as a polynomial in w^2, to w^10 (the series to
// w^11): the coefficients (2k)! / (4^k (k!)^2 (2k + 1)).
inline constexpr double kArcsineSeries[6] = {1.0,        1.0 / 6,      3.0 / 40,
                                             15.0 / 336, 105.0 / 3456, 945.0 / 42240};

// The angle in [0, pi] of the direction (cos, sin) = (back ? -c : c, s), from s >= 0 and c >= 0
// of unit length to rounding, with w scaled by k (arc_angle's correction of the length; 1 for a
// pair of unit length). Below 45 degrees it is the table angle a of (u, v) = (s, c), to 90
// pi / 2 - a of the swapped pair, to 135 pi / 2 + a, beyond pi - a (octant_base_sign). asin(w) is
// its Taylor series to w^11: the first omitted term, (63 / 2816) w^13, is below 1e-25, far below
// the rounding of theta_j (1e-16). It is evaluated in Estrin's form (simd::estrin), three
// independent products instead of Horner's chain of five: the near field's table rung waits for
// these angles at both ends of every ray, and took 6 % less time so. Written once for one value
// and for four lanes (T = double or simd::D4: the four-lane kernels of geometry/ and the table
// rung), the same bits in each lane (tests/util/simd_test.cpp).
template <class T>
LUXGRID_LANE T octant_table_angle(const T& s, const T& c, const simd::Mask<T>& back, const T& k) {
  const T u = simd::min(s, c), v = simd::max(s, c);
  T base, sign, row_sin, row_cos, row_angle;
  octant_base_sign(s > c, back, base, sign);
  angle_table_rows(u * (kAngleTableBins * 1.4142135623730951), row_sin, row_cos, row_angle);
  const T w = k * (u * row_cos - v * row_sin);
  const T series = w * simd::estrin(w * w, kArcsineSeries);
  return base + sign * (row_angle + series);
}

// The angle in [0, pi / 2] of (cos, sin) = (cos_a, sin_a), both >= 0 and of unit length to
// rounding: what std::atan2(sin_a, cos_a) gives, within 4 units in the last place.
template <class T>
LUXGRID_LANE T quadrant_angle(const T& sin_a, const T& cos_a) {
  return octant_table_angle(sin_a, cos_a, simd::Mask<T>{}, simd::splat<T>(1.0));
}

// A pair (sin, cos) counts as of unit length when |sin^2 + cos^2 - 1| is at most this: then
// k = (3 - sin^2 - cos^2) / 2, one Newton step for 1 / sqrt(sin^2 + cos^2) from 1, scales it to
// unit length within (3 / 8) (2^-27)^2 = 2e-17, a tenth of a unit in the last place. (Only w is
// scaled: the bin and the octant need the pair to rounding only.)
inline constexpr double kUnitPairTolerance = 0x1p-27;

// Whether the table gives arc_angle's angle of the pair (sin_a, cos_a), r2 = sin_a^2 + cos_a^2:
// of unit length (kUnitPairTolerance) and sin_a >= +0; and that angle.
template <class T>
LUXGRID_LANE simd::Mask<T> is_unit_pair(const T& sin_a, const T& r2) {
  return simd::logical_and(simd::abs(r2 - 1.0) <= kUnitPairTolerance,
                           simd::logical_not(simd::signbit(sin_a)));
}
template <class T>
LUXGRID_LANE T unit_pair_angle(const T& sin_a, const T& cos_a, const T& r2) {
  return octant_table_angle(sin_a, simd::abs(cos_a), cos_a < 0.0, 1.5 - 0.5 * r2);
}

// The angle in [0, pi] of (cos, sin) = (cos_a, sin_a), sin_a >= +0: std::atan2(sin_a, cos_a)
// within 4 units in the last place. Meant for a sine and cosine computed from unit vectors (the
// arc between a and b: |a x b| and a . b; a direction's gamma), which are of unit length only to
// rounding: the pair is scaled to unit length first (to second order, kUnitPairTolerance), so the
// angle stays as exact as atan2's, which ignores the length, also for tiny angles. Any other pair
// (not of unit length, a negative sin_a (-0 too) or NaN) takes std::atan2 itself.
inline double arc_angle(double sin_a, double cos_a) {
  const double r2 = sin_a * sin_a + cos_a * cos_a;
  if (!is_unit_pair(sin_a, r2)) return std::atan2(sin_a, cos_a);
  return unit_pair_angle(sin_a, cos_a, r2);
}

// The direction of the in-plane vector (x, y) in (-pi, pi]: std::atan2(y, x) to a few units in
// the last place, from the same table, for any length. (0, 0) gives 0; a negative zero y gives
// +pi where atan2 gives -pi (the same direction). Over T (one value or lanes): the lanes of (0, 0)
// compute a NaN that is not selected.
template <class T>
LUXGRID_LANE T direction_angle(const T& y, const T& x) {
  const T ax = simd::abs(x), ay = simd::abs(y);
  const T big = simd::max(ax, ay);
  const T t = simd::min(ax, ay) / big;  // tan of the angle to the nearer axis, <= 1
  const T c = 1.0 / simd::sqrt(1.0 + t * t);
  // (|y|, |x|) / |(x, y)| is (t c, c) or (c, t c).
  const simd::Mask<T> flat = ay <= ax;
  const T one = simd::splat<T>(1.0);
  const T a = quadrant_angle(simd::select(flat, t, one) * c, simd::select(flat, one, t) * c);
  const T q = simd::select(x < 0.0, kPi - a, a);
  return simd::select(big > 0.0, simd::select(y < 0.0, -q, q), simd::splat<T>(0.0));
}

// The direction of the unit vector (x, y) (of unit length to rounding) in (-pi, pi]: what
// direction_angle gives, without its normalisation (a square root and two divisions) for a
// direction already at hand; a negative zero y gives +pi as there.
inline double unit_direction_angle(double y, double x) {
  const double a = arc_angle(std::abs(y), x);
  return y < 0.0 ? -a : a;
}

}  // namespace luxgrid
