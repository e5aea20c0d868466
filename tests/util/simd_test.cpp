// util/simd.h: each helper performs on every lane what its one-value overload performs (so a
// kernel's scalar and four-lane instantiations give the same bits), the polynomial evaluator's
// order of operations, and util/table_angle.h's angles over lanes against one by one, in each
// version the multiversioning macro makes (the AVX2 one skipped on a processor without it).
#include "util/simd.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "util/table_angle.h"

namespace luxgrid {
namespace {

using simd::D4;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Estrin's form for six coefficients is ((c0 + x c1) + x^2 (c2 + x c3)) + x^4 (c4 + x c5), each
// product and sum in that order: the arcsine series as octant_table_angle wrote it by hand.
TEST(Simd, EstrinHasItsFixedOrderOfOperations) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-0.02, 0.02);
  for (int i = 0; i < 100000; ++i) {
    const double w = u(rng), w2 = w * w, w4 = w2 * w2, w8 = w4 * w4;
    const double by_hand = (1.0 + w2 * (1.0 / 6)) + w4 * (3.0 / 40 + w2 * (15.0 / 336)) +
                           w8 * (105.0 / 3456 + w2 * (945.0 / 42240));
    ASSERT_TRUE(same_bits(simd::estrin(w2, kArcsineSeries), by_hand)) << w;
  }
  // Three coefficients: (c0 + x c1) + x^2 c2; one: c0.
  const double c3[3] = {1.0, 2.0, 3.0}, c1[1] = {7.0};
  EXPECT_EQ(simd::estrin(0.5, c3), (1.0 + 0.5 * 2.0) + 0.25 * 3.0);
  EXPECT_EQ(simd::estrin(0.5, c1), 7.0);
  // Horner: c0 + x (c1 + x c2).
  EXPECT_EQ(simd::horner(0.5, c3), 1.0 + 0.5 * (2.0 + 0.5 * 3.0));
}

// The helpers lane by lane against one value, on values that tell min from max and NaN from a
// number: signed zeros, NaN, infinities.
TEST(Simd, HelpersActOnEachLaneAsOnOneValue) {
  const double nan = std::numeric_limits<double>::quiet_NaN(),
               inf = std::numeric_limits<double>::infinity();
  const std::vector<double> values = {0.0, -0.0, 1.0, -2.5, nan, -nan, inf, -inf, 1e-310};
  for (double a0 : values)
    for (double b0 : values) {
      const D4 a = {a0, b0, -a0, 3.0}, b = {b0, a0, b0, -0.0};
      const D4 mn = simd::min(a, b), mx = simd::max(a, b), ab = simd::abs(a);
      const D4 sq = simd::sqrt(ab);
      const simd::L4 sign = simd::signbit(a);
      for (int l = 0; l < 4; ++l) {
        EXPECT_TRUE(same_bits(mn[l], std::min(a[l], b[l]))) << a[l] << " " << b[l];
        EXPECT_TRUE(same_bits(mx[l], std::max(a[l], b[l]))) << a[l] << " " << b[l];
        EXPECT_TRUE(same_bits(ab[l], std::abs(a[l]))) << a[l];
        EXPECT_TRUE(same_bits(sq[l], std::sqrt(std::abs(a[l])))) << a[l];
        EXPECT_EQ(sign[l] != 0, std::signbit(a[l])) << a[l];
      }
    }
  const D4 v = {1e16, 1.0, -1e16, 1.0};
  EXPECT_EQ(simd::sum_in_order(v), ((1e16 + 1.0) - 1e16) + 1.0);  // 1: the order shows
}

// The dot product in four partial sums against four scalar sums, on lengths that leave every
// tail, with terms of very different sizes (the order of the additions shows in the bits).
TEST(Simd, DotInFourSumsIsFourScalarSums) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0), e(-20.0, 20.0);
  for (size_t n = 0; n < 40; ++n) {
    std::vector<float> a(n);
    std::vector<double> x(n);
    for (size_t j = 0; j < n; ++j)
      a[j] = static_cast<float>(u(rng)), x[j] = u(rng) * std::exp2(e(rng));
    for (size_t b = 0; b <= std::min<size_t>(n, 3); ++b) {
      double s[4] = {0.0, 0.0, 0.0, 0.0};
      size_t j = b;
      for (; j + 4 <= n; j += 4)
        for (int l = 0; l < 4; ++l) s[l] += static_cast<double>(a[j + l]) * x[j + l];
      for (; j < n; ++j) s[0] += static_cast<double>(a[j]) * x[j];
      const double want = (s[0] + s[1]) + (s[2] + s[3]);
      EXPECT_TRUE(same_bits(simd::dot_in_four_sums(a.data(), x.data(), b, n), want)) << n;
    }
  }
}

// The table angles over four lanes, in each version of a multiversioned kernel made here by the
// macro: arc_angle's (unit pairs, the table's branch) and direction_angle's (any pair, zeros).
LUXGRID_LANE void angles4_kernel(const double* s, const double* c, const double* y, const double* x,
                                 double* arc, double* direction) {
  const D4 sin_a = simd::load<D4>(s), cos_a = simd::load<D4>(c);
  const D4 r2 = sin_a * sin_a + cos_a * cos_a;
  simd::store(unit_pair_angle(sin_a, cos_a, r2), arc);
  simd::store(direction_angle(simd::load<D4>(y), simd::load<D4>(x)), direction);
}
LUXGRID_MULTIVERSION(void, angles4,
                     (const double* s, const double* c, const double* y, const double* x,
                      double* arc, double* direction),
                     (s, c, y, x, arc, direction), angles4_kernel)

using Angles4 = void (*)(const double*, const double*, const double*, const double*, double*,
                         double*);
void expect_angles_same_bits_as_one_by_one(Angles4 angles) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> theta(0.0, kPi), u(-2.0, 2.0);
  int differ = 0;
  for (int i = 0; i < 50000; ++i) {
    double s[4], c[4], y[4], x[4], arc[4], direction[4];
    for (int l = 0; l < 4; ++l) {
      const double t = (i + l) % 5 == 0 ? std::exp2(-40.0 * theta(rng)) : theta(rng);
      s[l] = std::sin(t), c[l] = std::cos(t);
      y[l] = u(rng), x[l] = u(rng);
      if ((i + l) % 7 == 0) y[l] = 0.0;                   // on an axis
      if ((i + l) % 11 == 0) x[l] = 0.0, y[l] = -0.0;     // the zero vector
      if ((i + l) % 13 == 0) x[l] = 1e-300, y[l] = -1.0;  // a denormal quotient
    }
    angles(s, c, y, x, arc, direction);
    for (int l = 0; l < 4; ++l) {
      // unit_pair_angle is arc_angle's table branch: every pair here is a unit pair.
      differ += !same_bits(arc[l], arc_angle(s[l], c[l]));
      differ += !same_bits(direction[l], direction_angle(y[l], x[l]));
    }
  }
  EXPECT_EQ(differ, 0);
}

TEST(Simd, TableAnglesOnLanesSameBitsAsOneByOneAvx2) {
  if (!simd::cpu_has_avx2()) GTEST_SKIP() << "this processor has no AVX2";
  expect_angles_same_bits_as_one_by_one(angles4_avx2);
}
TEST(Simd, TableAnglesOnLanesSameBitsAsOneByOneDefault) {
  expect_angles_same_bits_as_one_by_one(angles4_default);
}
TEST(Simd, TableAnglesOnLanesSameBitsAsOneByOneDispatched) {
  expect_angles_same_bits_as_one_by_one(angles4);  // the version this processor runs
}

}  // namespace
}  // namespace luxgrid
