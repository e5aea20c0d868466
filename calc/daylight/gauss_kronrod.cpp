#include "calc/daylight/gauss_kronrod.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>

namespace luxgrid::daylight {
namespace {

// QK15's nodes (the positive half; 0 last) and weights [Piessens1983]: the Kronrod nodes at odd
// indices, the Gauss nodes at even indices 1, 3, 5 and the centre.
constexpr std::array<double, 8> kNodes{
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
constexpr std::array<double, 8> kKronrodWeights{
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
// The 7-point Gauss weights of the nodes 1, 3, 5 and the centre.
constexpr std::array<double, 4> kGaussWeights{
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

struct Interval {
  double a, b, value, error;
  bool operator<(const Interval& other) const { return error < other.error; }
};

Interval qk15(const std::function<double(double)>& f, double a, double b) {
  const double centre = 0.5 * (a + b), half = 0.5 * (b - a);
  const double fc = f(centre);
  double kronrod = fc * kKronrodWeights[7], gauss = fc * kGaussWeights[3];
  for (int i = 0; i < 7; ++i) {
    const double dx = half * kNodes[i];
    const double pair = f(centre - dx) + f(centre + dx);
    kronrod += kKronrodWeights[i] * pair;
    if (i % 2 == 1) gauss += kGaussWeights[i / 2] * pair;
  }
  return {a, b, kronrod * half, std::abs(kronrod - gauss) * half};
}

}  // namespace

QuadratureResult integrate_adaptive(const std::function<double(double)>& f, double a, double b,
                                    double relative_tolerance, double absolute_tolerance,
                                    const std::vector<double>& breakpoints, int max_intervals) {
  std::vector<double> cuts{a};
  std::vector<double> inner = breakpoints;
  std::sort(inner.begin(), inner.end());
  for (double x : inner)
    if (x > a && x < b) cuts.push_back(x);
  cuts.push_back(b);
  std::priority_queue<Interval> queue;
  QuadratureResult result;
  for (size_t i = 0; i + 1 < cuts.size(); ++i) {
    if (!(cuts[i + 1] > cuts[i])) continue;
    const Interval piece = qk15(f, cuts[i], cuts[i + 1]);
    result.value += piece.value, result.error_estimate += piece.error;
    result.evaluations += 15;
    queue.push(piece);
  }
  while (!queue.empty() && static_cast<int>(queue.size()) < max_intervals &&
         result.error_estimate >
             std::max(absolute_tolerance, relative_tolerance * std::abs(result.value))) {
    const Interval worst = queue.top();
    queue.pop();
    const double middle = 0.5 * (worst.a + worst.b);
    if (!(middle > worst.a && middle < worst.b)) break;  // at the resolution of doubles
    const Interval left = qk15(f, worst.a, middle), right = qk15(f, middle, worst.b);
    result.value += left.value + right.value - worst.value;
    result.error_estimate += left.error + right.error - worst.error;
    result.evaluations += 30;
    queue.push(left), queue.push(right);
  }
  // The running sums drift by rounding: add the final intervals once more.
  result.value = 0.0, result.error_estimate = 0.0;
  while (!queue.empty()) {
    result.value += queue.top().value, result.error_estimate += queue.top().error;
    queue.pop();
  }
  return result;
}

}  // namespace luxgrid::daylight
