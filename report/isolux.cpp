#include "report/isolux.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace luxgrid::report {

namespace {

// The segments of the square with lower-left corner (i, j) and corner values v (counter-clockwise
// from (i, j): 0 (i,j), 1 (i+1,j), 2 (i+1,j+1), 3 (i,j+1)) at `level`, appended to `out`.
void square_segments(const double (&v)[4], int i, int j, double level,
                     std::vector<IsoSegment>& out) {
  int code = 0;
  for (int k = 0; k < 4; ++k) code |= (v[k] >= level ? 1 : 0) << k;
  if (code == 0 || code == 15) return;
  // Where along the edge from value a to value b the level lies (0..1).
  auto t_of = [&](double a, double b) { return a == b ? 0.5 : (level - a) / (b - a); };
  // Edge e joins corner e and corner (e + 1) % 4; its crossing point:
  auto edge = [&](int e, double& x, double& y) {
    const int a = e, b = (e + 1) % 4;
    const double t = t_of(v[a], v[b]);
    const double cx[4] = {0, 1, 1, 0}, cy[4] = {0, 0, 1, 1};
    x = i + cx[a] + t * (cx[b] - cx[a]);
    y = j + cy[a] + t * (cy[b] - cy[a]);
  };
  auto seg = [&](int e0, int e1) {
    IsoSegment s{};
    edge(e0, s.x0, s.y0);
    edge(e1, s.x1, s.y1);
    out.push_back(s);
  };
  // An edge is crossed when its two corners are on different sides.
  int crossed[4], n = 0;
  for (int e = 0; e < 4; ++e) {
    const bool a = (code >> e) & 1, b = (code >> ((e + 1) % 4)) & 1;
    if (a != b) crossed[n++] = e;
  }
  if (n == 2) {
    seg(crossed[0], crossed[1]);
  } else {  // saddle (codes 5 and 10): all four edges crossed
    const double centre = (v[0] + v[1] + v[2] + v[3]) / 4.0;
    const bool corner0_high = code & 1;
    // If the centre is on corner 0's side, corners 0 and 2 are joined through the middle,
    // so the lines cut off corners 1 and 3; otherwise they cut off corners 0 and 2.
    if ((centre >= level) == corner0_high) {
      seg(0, 1);  // around corner 1
      seg(2, 3);  // around corner 3
    } else {
      seg(3, 0);  // around corner 0
      seg(1, 2);  // around corner 2
    }
  }
}

}  // namespace

std::vector<IsoSegment> isolux_segments(const std::vector<double>& E, int nu, int nv, double level,
                                        const std::vector<bool>& active) {
  return std::move(isolux_segments(E, nu, nv, std::vector<double>{level}, active)[0]);
}

std::vector<std::vector<IsoSegment>> isolux_segments(const std::vector<double>& E, int nu, int nv,
                                                     const std::vector<double>& levels,
                                                     const std::vector<bool>& active) {
  std::vector<std::vector<IsoSegment>> out(levels.size());
  if (nu < 2 || nv < 2 || E.size() < static_cast<size_t>(nu) * nv) return out;
  auto at = [&](int i, int j) { return E[static_cast<size_t>(j) * nu + i]; };
  std::vector<unsigned char> on(static_cast<size_t>(nu) * nv, 1);
  for (size_t k = 0; k < active.size() && k < on.size(); ++k) on[k] = active[k];
  // The levels in ascending order: a square crosses those in (lowest corner, highest corner],
  // found by a binary search instead of a test of every level (a 10^6-point grid's fine field has
  // 10^6 squares, most of them crossed by none). A NaN level crosses nothing (no corner is at or
  // above it).
  std::vector<size_t> order;
  for (size_t k = 0; k < levels.size(); ++k)
    if (!std::isnan(levels[k])) order.push_back(k);
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return levels[a] < levels[b]; });
  std::vector<double> sorted(order.size());
  for (size_t k = 0; k < order.size(); ++k) sorted[k] = levels[order[k]];
  for (int j = 0; j + 1 < nv; ++j) {
    const unsigned char* on0 = on.data() + static_cast<size_t>(j) * nu;
    const unsigned char* on1 = on0 + nu;
    for (int i = 0; i + 1 < nu; ++i) {
      if (!on0[i] || !on0[i + 1] || !on1[i + 1] || !on1[i]) continue;
      const double v[4] = {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
      // A level is crossed when a corner is at or above it and one below: lowest < level <=
      // highest. A NaN corner is never at or above: such a square tries every level.
      if (std::isnan(v[0]) || std::isnan(v[1]) || std::isnan(v[2]) || std::isnan(v[3])) {
        for (size_t k : order) square_segments(v, i, j, levels[k], out[k]);
        continue;
      }
      const double lo = std::min({v[0], v[1], v[2], v[3]}), hi = std::max({v[0], v[1], v[2], v[3]});
      for (size_t k = std::upper_bound(sorted.begin(), sorted.end(), lo) - sorted.begin();
           k < sorted.size() && sorted[k] <= hi; ++k)
        square_segments(v, i, j, sorted[k], out[order[k]]);
    }
  }
  return out;
}

std::vector<double> isolux_levels(const ColourScale& scale, double emin, double emax) {
  std::vector<double> out;
  for (double t : scale.ticks) {
    if (t > scale.min && t < scale.max && t > emin && t < emax) out.push_back(t);
  }
  return out;
}

}  // namespace luxgrid::report
