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

}  // namespace luxgrid::geometry
