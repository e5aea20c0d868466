// Adaptive Gauss-Kronrod (calc/daylight/gauss_kronrod.h): exact for polynomials up to degree 22
// on one interval (the 15-point Kronrod rule's degree is 3 x 7 + 1), and converged to its
// tolerance on integrands with a kink and with a steep peak, against their closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "calc/daylight/gauss_kronrod.h"

namespace luxgrid::daylight {
namespace {

TEST(GaussKronrod, ExactForDegree22) {
  for (int k = 0; k <= 22; ++k) {
    const QuadratureResult r =
        integrate_adaptive([k](double x) { return std::pow(x, k); }, 0.0, 1.0, 1e-14, 0.0, {}, 1);
    EXPECT_NEAR(r.value, 1.0 / (k + 1), 1e-15) << "x^" << k;
  }
}

// |x - 0.3| on [0, 1]: 0.3^2 / 2 + 0.7^2 / 2 = 0.29; the kink at a breakpoint is integrated
// exactly, and without the breakpoint the bisection still converges to the tolerance.
TEST(GaussKronrod, KinkWithAndWithoutBreakpoint) {
  const auto f = [](double x) { return std::abs(x - 0.3); };
  EXPECT_NEAR(integrate_adaptive(f, 0.0, 1.0, 1e-12, 0.0, {0.3}).value, 0.29, 1e-15);
  const QuadratureResult r = integrate_adaptive(f, 0.0, 1.0, 1e-9, 0.0);
  EXPECT_NEAR(r.value, 0.29, 1e-9);
  EXPECT_LE(r.error_estimate, 1e-9 * 0.29);
}

// exp(-3 x) over [0, pi]: (1 - exp(-3 pi)) / 3, the CIE indicatrix's steepest exponential.
TEST(GaussKronrod, ExponentialToTolerance) {
  const QuadratureResult r =
      integrate_adaptive([](double x) { return std::exp(-3.0 * x); }, 0.0, M_PI, 1e-12, 0.0);
  EXPECT_NEAR(r.value, (1.0 - std::exp(-3.0 * M_PI)) / 3.0, 1e-14);
}

}  // namespace
}  // namespace luxgrid::daylight
