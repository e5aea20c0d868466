#pragma once
// Gauss-Legendre rules on [-1, 1]: m nodes and weights, exact for polynomials of degree 2m - 1
// (Abramowitz and Stegun 25.4.29 [AbramowitzStegun1964]). The nodes are the roots of the Legendre
// polynomial P_m, found by Newton's iteration from Tricomi's estimate cos(pi (i + 3/4) / (m + 1/2))
// and the recurrence (k + 1) P_k+1 = (2k + 1) x P_k - k P_k-1; the weights are
// 2 / ((1 - x^2) P_m'(x)^2). Made once, to rounding (the tests check them against the published
// values and the exactness).
#include <array>
#include <cmath>

#include "util/robust_math.h"

namespace luxgrid::nearfield {

inline constexpr int kMaxGaussLegendrePoints = 9;

struct GaussLegendreRule {
  int points = 0;
  std::array<double, kMaxGaussLegendrePoints> x{}, w{};  // ascending nodes, their weights
};

// The m-point rule, 1 <= m <= kMaxGaussLegendrePoints (clamped).
inline const GaussLegendreRule& gauss_legendre(int m) {
  static const std::array<GaussLegendreRule, kMaxGaussLegendrePoints + 1> rules = [] {
    std::array<GaussLegendreRule, kMaxGaussLegendrePoints + 1> out{};
    for (int n = 1; n <= kMaxGaussLegendrePoints; ++n) {
      GaussLegendreRule& r = out[n];
      r.points = n;
      for (int i = 0; i < n; ++i) {
        double x = std::cos(kPi * (i + 0.75) / (n + 0.5));  // the i-th root from the right
        double dp = 1.0;
        for (int iteration = 0; iteration < 100; ++iteration) {
          double p0 = 1.0, p1 = x;  // P_0, P_1
          for (int k = 1; k < n; ++k) {
            const double p2 = ((2 * k + 1) * x * p1 - k * p0) / (k + 1);
            p0 = p1, p1 = p2;
          }
          dp = n * (x * p1 - p0) / (x * x - 1.0);  // P_n'(x) from P_n and P_n-1
          const double step = p1 / dp;
          x -= step;
          if (std::abs(step) < 1e-17) break;
        }
        r.x[n - 1 - i] = x;
        r.w[n - 1 - i] = 2.0 / ((1.0 - x * x) * dp * dp);
      }
    }
    return out;
  }();
  return rules[m < 1 ? 1 : (m > kMaxGaussLegendrePoints ? kMaxGaussLegendrePoints : m)];
}

}  // namespace luxgrid::nearfield
