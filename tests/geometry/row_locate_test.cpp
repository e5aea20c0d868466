// RowLocator must give geometry::locate's answer for every point, not only most: the plots draw
// with it, and a pixel classified differently would change a picture. Checked on points where
// the two could part: on edges and corners, on the rows of horizontal edges and of vertices, a
// rounding error away from an edge, and off the prepared row.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "geometry/row_locate.h"

namespace luxgrid::geometry {
namespace {

// An L with horizontal and vertical edges, a rotated rectangle (the footprint of a turned
// cabinet), a triangle with a nearly horizontal edge, and a polygon with a repeated corner (a
// zero-length edge).
const std::vector<Polygon2> kPolygons = {
    {{0, 0}, {6, 0}, {6, 3}, {3, 3}, {3, 6}, {0, 6}},
    {{2.0, 1.0}, {3.2990381, 1.75}, {2.7990381, 2.6160254}, {1.5, 1.8660254}},
    {{0, 0}, {10, 1e-7}, {5, 4}},
    {{0, 0}, {4, 0}, {4, 0}, {4, 3}, {0, 3}},
};

// The rows a raster would use plus every corner's y and values a unit in the last place away.
std::vector<double> rows_for(const Polygon2& poly) {
  std::vector<double> ys;
  for (int k = -20; k <= 80; ++k) ys.push_back(k * 0.0917);
  for (const Vec2& v : poly) {
    ys.push_back(v.y);
    ys.push_back(std::nextafter(v.y, -1e9));
    ys.push_back(std::nextafter(v.y, 1e9));
  }
  return ys;
}

// Points of row y: a regular sweep, every crossing of an edge and a unit in the last place on
// either side, every corner's x.
std::vector<double> xs_for(const Polygon2& poly, double y) {
  std::vector<double> xs;
  for (int k = -20; k <= 120; ++k) xs.push_back(k * 0.0731);
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 &a = poly[j], &b = poly[i];
    xs.push_back(a.x);
    if ((b.y > y) != (a.y > y)) {
      const double x = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
      xs.push_back(x);
      xs.push_back(std::nextafter(x, -1e9));
      xs.push_back(std::nextafter(x, 1e9));
    }
  }
  return xs;
}

TEST(RowLocator, AgreesWithLocateEverywhereIncludingEdgesAndCorners) {
  long compared = 0, on_boundary = 0;
  for (double tol : {0.0, 1e-9, 0.05}) {
    for (const Polygon2& poly : kPolygons) {
      RowLocator row(poly, tol);
      for (double y : rows_for(poly)) {
        row.set_row(y);
        for (double x : xs_for(poly, y)) {
          const Vec2 p(x, y);
          const Location expected = locate(p, poly, tol);
          ASSERT_EQ(row.locate(p), expected) << "x " << x << " y " << y << " tol " << tol;
          ++compared;
          on_boundary += expected == Location::boundary;
        }
      }
    }
  }
  // The sweep did reach the cases that matter: many points on an edge, far more elsewhere.
  EXPECT_GT(on_boundary, 500);
  EXPECT_GT(compared, 50000);
}

TEST(RowLocator, ARowAtOnceAgreesWithLocateForEveryPoint) {
  // locate_row walks the row once for ascending xs, writing spans between crossings at once: the
  // points above (every crossing and a unit in the last place either side, every corner), a
  // raster's regular sweep with repeated x, and the same in shuffled order, descending, and with
  // NaN and infinities among them.
  std::mt19937 rng(11);
  long compared = 0;
  for (double tol : {0.0, 1e-9, 0.05}) {
    for (const Polygon2& poly : kPolygons) {
      RowLocator row(poly, tol);
      for (double y : rows_for(poly)) {
        row.set_row(y);
        std::vector<double> xs = xs_for(poly, y);
        for (int k = 0; k < 400; ++k) xs.push_back(-1.5 + k * 0.0291);
        xs.push_back(xs[5]), xs.push_back(xs[5]);
        std::sort(xs.begin(), xs.end());
        std::vector<double> shuffled = xs, descending(xs.rbegin(), xs.rend()), odd = xs;
        std::shuffle(shuffled.begin(), shuffled.end(), rng);
        odd.insert(odd.begin() + static_cast<long>(odd.size() / 2), NAN);
        odd.insert(odd.begin(), NAN), odd.push_back(INFINITY), odd.push_back(-INFINITY);
        for (const auto* order : {&xs, &shuffled, &descending, &odd}) {
          std::vector<Location> got(order->size(), Location::boundary);
          row.locate_row(*order, got);
          for (size_t k = 0; k < order->size(); ++k) {
            const Vec2 p((*order)[k], y);
            ASSERT_EQ(got[k], locate(p, poly, tol)) << "x " << p.x << " y " << y << " tol " << tol;
            ++compared;
          }
        }
      }
    }
  }
  EXPECT_GT(compared, 500000);
  // Before any row is prepared the points are on y = 0, located one by one.
  RowLocator fresh(kPolygons[0], 0.0);
  const std::vector<double> xs = {-1, 1, 3, 7};
  std::vector<Location> got(xs.size());
  fresh.locate_row(xs, got);
  for (size_t k = 0; k < xs.size(); ++k) EXPECT_EQ(got[k], locate({xs[k], 0.0}, kPolygons[0], 0.0));
}

TEST(RowLocator, PointsOffThePreparedRowAreAnsweredToo) {
  const Polygon2& l = kPolygons[0];
  RowLocator row(l, 0.0);
  row.set_row(1.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-1.0, 7.0);
  for (int k = 0; k < 20000; ++k) {
    const Vec2 p(coordinate(rng), coordinate(rng));
    ASSERT_EQ(row.locate(p), locate(p, l, 0.0)) << p.x << " " << p.y;
  }
  // Without a prepared row at all.
  RowLocator fresh(l, 0.0);
  EXPECT_EQ(fresh.locate({1, 1}), Location::inside);
  EXPECT_EQ(fresh.locate({4, 4}), Location::outside);
  EXPECT_EQ(fresh.locate({3, 4}), Location::boundary);
}

}  // namespace
}  // namespace luxgrid::geometry
