// The loops of reflected light over many sources (calc/indirect/far_kernels.h), in each version
// the multiversioning macro makes, against the formulas one term at a time, bit for bit: the far
// form factors against point_kernel_form_factor (the dense matrix's scalar kernel), the gather's
// far terms against point_kernel_pi_per_m2 of glm's dot products, the row sums against four
// scalar partial sums.
#include "calc/indirect/far_kernels.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

namespace luxgrid::calc::indirect {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Sources on a ceiling (normal down) in front of a receiver on the floor (normal up) and of a
// wall receiver, every pair in front of each other (the kernels' precondition), at distances
// from a centimetre to tens of metres; counts that leave every tail of a vector loop.
struct Sources {
  std::vector<double> x, y, z, flux;
};
Sources ceiling_sources(std::mt19937_64& rng, size_t count) {
  std::uniform_real_distribution<double> u(-20.0, 20.0), f(0.0, 100.0);
  std::uniform_real_distribution<double> h(0.01, 10.0);
  Sources s;
  for (size_t k = 0; k < count; ++k) {
    s.x.push_back(u(rng)), s.y.push_back(u(rng)), s.z.push_back(h(rng)), s.flux.push_back(f(rng));
  }
  return s;
}

using FarFormFactors = void (*)(const double*, const double*, const double*, std::size_t,
                                const Vec3&, const Vec3&, const Vec3&, double, double*);
void expect_form_factors_same_bits(FarFormFactors far) {
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  int differ = 0;
  for (size_t count = 1; count <= 37; ++count) {
    const Sources s = ceiling_sources(rng, count);
    const Vec3 dc(u(rng), u(rng), 0.0), dn(0.0, 0.0, 1.0), sn(0.0, 0.0, -1.0);
    const double area = 0.3;
    std::vector<double> out(count);
    far(s.x.data(), s.y.data(), s.z.data(), count, dc, dn, sn, area, out.data());
    for (size_t k = 0; k < count; ++k) {
      // The receiver (dc, dn) seen from the source (o, sn): point_kernel_form_factor(x, n, c, m).
      const double one = point_kernel_form_factor(dc, dn, Vec3(s.x[k], s.y[k], s.z[k]), sn, area);
      differ += !same_bits(out[k], one);
    }
  }
  EXPECT_EQ(differ, 0);
}

TEST(FarKernels, FormFactorsSameBitsAsOneByOneAvx2) {
  if (!simd::cpu_has_avx2()) GTEST_SKIP() << "this processor has no AVX2";
  expect_form_factors_same_bits(far_form_factors_avx2);
}
TEST(FarKernels, FormFactorsSameBitsAsOneByOneDefault) {
  expect_form_factors_same_bits(far_form_factors_default);
}

using FarTerms = void (*)(const double*, const double*, const double*, const double*, std::size_t,
                          const Vec3&, const Vec3&, const Vec3&, double, double, double*);
void expect_terms_same_bits(FarTerms far) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  int differ = 0, in_band = 0;
  for (size_t count = 1; count <= 37; ++count) {
    const Sources s = ceiling_sources(rng, count);
    const Vec3 x(u(rng), u(rng), 0.0), n(0.0, 0.0, 1.0), m(0.0, 0.0, -1.0);
    const double inner2 = 4.0, outer2 = 400.0;
    std::vector<double> out(count);
    far(s.x.data(), s.y.data(), s.z.data(), s.flux.data(), count, x, n, m, inner2, outer2,
        out.data());
    for (size_t k = 0; k < count; ++k) {
      const Vec3 d = x - Vec3(s.x[k], s.y[k], s.z[k]);
      const double d2 = glm::dot(d, d);
      const double one =
          d2 >= inner2 && d2 < outer2
              ? s.flux[k] * point_kernel_pi_per_m2(glm::dot(m, d), -glm::dot(n, d), d2)
              : 0.0;
      differ += !same_bits(out[k], one);
      in_band += d2 >= inner2 && d2 < outer2;
    }
  }
  EXPECT_EQ(differ, 0);
  EXPECT_GT(in_band, 300);  // the band holds most terms, and leaves some out
}

TEST(FarKernels, TermsSameBitsAsOneByOneAvx2) {
  if (!simd::cpu_has_avx2()) GTEST_SKIP() << "this processor has no AVX2";
  expect_terms_same_bits(far_terms_avx2);
}
TEST(FarKernels, TermsSameBitsAsOneByOneDefault) { expect_terms_same_bits(far_terms_default); }

using RowDot = double (*)(const float*, const double*, std::size_t, std::size_t);
void expect_row_dot_is_four_sums(RowDot dot) {
  std::mt19937_64 rng(43);
  std::uniform_real_distribution<double> u(0.0, 1.0), e(-30.0, 30.0);
  for (size_t n = 0; n < 70; ++n) {
    std::vector<float> row(n);
    std::vector<double> v(n);
    for (size_t j = 0; j < n; ++j)
      row[j] = static_cast<float>(u(rng)), v[j] = u(rng) * std::exp2(e(rng));
    for (size_t b = 0; b <= std::min<size_t>(n, 5); ++b) {
      double s[4] = {0.0, 0.0, 0.0, 0.0};
      size_t j = b;
      for (; j + 4 <= n; j += 4)
        for (int l = 0; l < 4; ++l) s[l] += static_cast<double>(row[j + l]) * v[j + l];
      for (; j < n; ++j) s[0] += static_cast<double>(row[j]) * v[j];
      EXPECT_TRUE(same_bits(dot(row.data(), v.data(), b, n), (s[0] + s[1]) + (s[2] + s[3])))
          << n << " from " << b;
    }
  }
}

TEST(FarKernels, RowDotIsFourScalarSumsAvx2) {
  if (!simd::cpu_has_avx2()) GTEST_SKIP() << "this processor has no AVX2";
  expect_row_dot_is_four_sums(row_dot_avx2);
}
TEST(FarKernels, RowDotIsFourScalarSumsDefault) { expect_row_dot_is_four_sums(row_dot_default); }

}  // namespace
}  // namespace luxgrid::calc::indirect
