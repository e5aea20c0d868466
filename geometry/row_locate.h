#pragma once
// locate() for many points on one horizontal line y = const, as a raster's row needs it: the
// edges the line crosses are found once per row, so each point costs a binary search instead of
// a pass over every edge. The answer is locate()'s own, bit for bit: the crossings are computed
// with locate()'s formula, and every point that could lie within `boundary_tol_m` of an edge (or
// whose y is not the row's) is handed to locate() itself.
#include <span>
#include <vector>

#include "geometry/polygon.h"

namespace luxgrid::geometry {

class RowLocator {
 public:
  // `poly` must outlive the locator.
  RowLocator(const Polygon2& poly, double boundary_tol_m);

  // Prepares the row y = `y`; locate() then answers for any point, fastest for those on it.
  void set_row(double y);

  // Exactly geometry::locate(p, poly, boundary_tol_m).
  Location locate(const Vec2& p) const;

  // locate() of each point (xs[k], y) of the prepared row into out[k] (as many as xs). Made for
  // xs that ascend (a raster row's pixels): one walk along the row's crossings and near-edge
  // ranges answers them all, a span of points between two crossings at once. Any order is
  // answered right, if more slowly.
  void locate_row(std::span<const double> xs, std::span<Location> out) const;

 private:
  const Polygon2& poly_;
  double tol_m_;
  double margin_m_;  // tol_m_ plus far more than the rounding of locate()'s distances
  double y_ = 0.0;
  bool row_set_ = false;
  std::vector<double> crossings_x_;  // sorted
  struct Interval {
    double x0, x1;
  };
  std::vector<Interval> near_edge_;  // x ranges of the row that may lie within tol of an edge,
                                     // by their start
};

}  // namespace luxgrid::geometry
