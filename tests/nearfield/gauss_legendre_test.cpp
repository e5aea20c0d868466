// Gauss-Legendre rules (calc/nearfield/gauss_legendre.h): the published nodes and weights, and
// the defining property, exactness to degree 2m - 1 (and not beyond).
#include <gtest/gtest.h>

#include <cmath>

#include "calc/nearfield/gauss_legendre.h"

namespace luxgrid::nearfield {
namespace {

// Abramowitz and Stegun, Table 25.4: m = 3, nodes 0 and +-sqrt(3/5), weights 8/9 and 5/9; m = 5,
// the largest node 0.906179845938664 with weight 0.236926885056189.
TEST(GaussLegendre, PublishedNodesAndWeights) {
  const GaussLegendreRule& r3 = gauss_legendre(3);
  ASSERT_EQ(r3.points, 3);
  EXPECT_NEAR(r3.x[0], -std::sqrt(0.6), 1e-15);
  EXPECT_NEAR(r3.x[1], 0.0, 1e-15);
  EXPECT_NEAR(r3.x[2], std::sqrt(0.6), 1e-15);
  EXPECT_NEAR(r3.w[0], 5.0 / 9.0, 1e-15);
  EXPECT_NEAR(r3.w[1], 8.0 / 9.0, 1e-15);
  const GaussLegendreRule& r5 = gauss_legendre(5);
  EXPECT_NEAR(r5.x[4], 0.906179845938664, 1e-14);
  EXPECT_NEAR(r5.w[4], 0.236926885056189, 1e-14);
  // The pair the rung's cells use: +-1/sqrt(3), weights 1.
  EXPECT_NEAR(gauss_legendre(2).x[1], 1.0 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(gauss_legendre(2).w[1], 1.0, 1e-15);
}

// Exact to rounding for x^k, k <= 2m - 1 (integral over [-1, 1]: 2 / (k + 1) for even k, 0 for
// odd), and off by more than rounding for x^2m: each rule is the m-point rule, not a finer one.
TEST(GaussLegendre, ExactToDegreeTwoMMinusOne) {
  for (int m = 1; m <= kMaxGaussLegendrePoints; ++m) {
    const GaussLegendreRule& r = gauss_legendre(m);
    ASSERT_EQ(r.points, m);
    for (int k = 0; k <= 2 * m; ++k) {
      double sum = 0.0;
      for (int i = 0; i < m; ++i) sum += r.w[i] * std::pow(r.x[i], k);
      const double exact = k % 2 == 0 ? 2.0 / (k + 1) : 0.0;
      if (k < 2 * m)
        EXPECT_NEAR(sum, exact, 1e-14) << "m " << m << ", x^" << k;
      else
        EXPECT_GT(std::abs(sum - exact), 1e-6) << "m " << m << ", x^" << k;
    }
    for (int i = 0; i + 1 < m; ++i) EXPECT_LT(r.x[i], r.x[i + 1]) << "m " << m;
  }
}

}  // namespace
}  // namespace luxgrid::nearfield
