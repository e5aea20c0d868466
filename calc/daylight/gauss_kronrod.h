#pragma once
// Adaptive Gauss-Kronrod quadrature on an interval: the 7-point Gauss rule and its 15-point
// Kronrod extension (QUADPACK's QK15 [Piessens1983]), the interval of largest error estimate
// bisected until the sum of the estimates is within the tolerance. The estimate of each interval
// is |K15 - G7|, which for a smooth integrand overstates the error of K15 by orders of magnitude,
// so the result is usually far better than the tolerance asked. Breakpoints (where the integrand
// has a kink, such as the sun's direction for a CIE sky) are given as the first subdivision.
#include <functional>
#include <vector>

namespace luxgrid::daylight {

struct QuadratureResult {
  double value = 0.0;
  double error_estimate = 0.0;  // the sum of |K15 - G7| over the final intervals
  int evaluations = 0;
};

// The integral of f over [a, b], split first at `breakpoints` (those strictly inside), refined
// until the error estimate is at most max(absolute_tolerance, relative_tolerance |value|) or
// max_intervals are made.
QuadratureResult integrate_adaptive(const std::function<double(double)>& f, double a, double b,
                                    double relative_tolerance, double absolute_tolerance,
                                    const std::vector<double>& breakpoints = {},
                                    int max_intervals = 2000);

}  // namespace luxgrid::daylight
