#include "geometry/row_locate.h"

#include <algorithm>
#include <cmath>

namespace luxgrid::geometry {

RowLocator::RowLocator(const Polygon2& poly, double boundary_tol_m)
    : poly_(poly), tol_m_(boundary_tol_m) {
  // locate()'s distances carry rounding errors of a few units in the last place of the
  // coordinates; 1e-9 of the largest coordinate (and at least 1e-9 m) is millions of times more.
  double extent = 1.0;
  for (const Vec2& v : poly_) extent = std::max({extent, std::abs(v.x), std::abs(v.y)});
  margin_m_ = tol_m_ + 1e-9 * extent;
}

void RowLocator::set_row(double y) {
  y_ = y;
  row_set_ = true;
  crossings_x_.clear();
  near_edge_.clear();
  const size_t n = poly_.size();
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = poly_[j];
    const Vec2& b = poly_[i];
    // The same expression as locate(), so the same crossings to the last bit.
    if ((b.y > y) != (a.y > y)) crossings_x_.push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
    // Points of the row within margin_m_ of segment ab: inside the segment's box grown by the
    // margin, and, unless ab is horizontal, within the margin of its line, a range of x.
    const double m = margin_m_;
    if (y < std::min(a.y, b.y) - m || y > std::max(a.y, b.y) + m) continue;
    double x0 = std::min(a.x, b.x) - m, x1 = std::max(a.x, b.x) + m;
    const double dy = b.y - a.y;
    if (dy != 0.0) {
      const double dx = b.x - a.x;
      const double x_line = a.x + dx * (y - a.y) / dy;
      // |dy (x - a.x) - dx (y - a.y)| <= m |ab|, with the margin doubled against its own rounding.
      const double half_width = 2.0 * m * std::hypot(dx, dy) / std::abs(dy);
      x0 = std::max(x0, x_line - half_width), x1 = std::min(x1, x_line + half_width);
    }
    if (x0 <= x1) near_edge_.push_back({x0, x1});
  }
  std::sort(crossings_x_.begin(), crossings_x_.end());
  std::sort(near_edge_.begin(), near_edge_.end(),
            [](const Interval& a, const Interval& b) { return a.x0 < b.x0; });
}

Location RowLocator::locate(const Vec2& p) const {
  if (!row_set_ || p.y != y_) return geometry::locate(p, poly_, tol_m_);
  for (const Interval& s : near_edge_)
    if (p.x >= s.x0 && p.x <= s.x1) return geometry::locate(p, poly_, tol_m_);
  // No edge within the tolerance: locate() returns its crossing parity, the number of crossings
  // right of p (`p.x < x`).
  const auto right =
      crossings_x_.end() - std::upper_bound(crossings_x_.begin(), crossings_x_.end(), p.x);
  return right % 2 == 1 ? Location::inside : Location::outside;
}

void RowLocator::locate_row(std::span<const double> xs, std::span<Location> out) const {
  if (!row_set_) {
    for (size_t k = 0; k < xs.size(); ++k) out[k] = locate(Vec2(xs[k], y_));
    return;
  }
  // locate()'s answers in one walk along the row: `crossed` counts the crossings at or left of x
  // (so crossings_x_.size() - crossed lie right of it, as upper_bound counts them), `edge` is
  // the first near-edge range that does not end left of x: x lies in a range only if it lies in
  // that one, as the later ones start no sooner. Away from the ranges the answer holds
  // from x until the next crossing or range, so it is written for the whole span at once. A step
  // back (or a NaN, which locate() finds outside, as an empty walk does) starts the walk again.
  size_t crossed = 0, edge = 0;
  const size_t crossings = crossings_x_.size(), ranges = near_edge_.size();
  double previous = -INFINITY;
  for (size_t k = 0; k < xs.size();) {
    const double x = xs[k];
    if (!(x >= previous)) crossed = 0, edge = 0;
    while (crossed < crossings && crossings_x_[crossed] <= x) ++crossed;
    while (edge < ranges && near_edge_[edge].x1 < x) ++edge;
    if (edge < ranges && near_edge_[edge].x0 <= x) {
      out[k++] = geometry::locate(Vec2(x, y_), poly_, tol_m_);
      previous = x;
      continue;
    }
    const Location answer = (crossings - crossed) % 2 == 1 ? Location::inside : Location::outside;
    const double end = std::min(crossed < crossings ? crossings_x_[crossed] : INFINITY,
                                edge < ranges ? near_edge_[edge].x0 : INFINITY);
    do out[k++] = answer;
    while (k < xs.size() && xs[k] >= x && xs[k] < end);
    previous = xs[k - 1];
  }
}

}  // namespace luxgrid::geometry
