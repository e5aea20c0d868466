// geometry::polygons_overlap on hand-drawn cases: shared interior area is overlap, a shared edge
// or corner is not. Side-by-side rectangles of one height overlapping along x are the case a
// test of proper edge crossings, corners and centroids alone misses (openings of one wall,
// project/project_daylight.cpp).
#include <gtest/gtest.h>

#include "geometry/polygon.h"

namespace luxgrid::geometry {
namespace {

Polygon2 box(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

TEST(PolygonsOverlap, SideBySideOfOneHeight) {
  // Windows 0.6-2.4 m and 2-4.9 m wide, both 0.9-2.7 m high: 0.4 x 1.8 m in common, no edge
  // crossing properly, every corner of each outside or on the other's boundary.
  EXPECT_TRUE(polygons_overlap(box(0.6, 0.9, 2.4, 2.7), box(2.0, 0.9, 4.9, 2.7)));
  EXPECT_TRUE(polygons_overlap(box(2.0, 0.9, 4.9, 2.7), box(0.6, 0.9, 2.4, 2.7)));
  // Clockwise input is the same polygon.
  Polygon2 cw = box(2.0, 0.9, 4.9, 2.7);
  std::reverse(cw.begin(), cw.end());
  EXPECT_TRUE(polygons_overlap(box(0.6, 0.9, 2.4, 2.7), cw));
}

TEST(PolygonsOverlap, TouchingIsNoOverlap) {
  EXPECT_FALSE(polygons_overlap(box(0, 0, 1, 1), box(1, 0, 2, 1)));      // a shared edge
  EXPECT_FALSE(polygons_overlap(box(0, 0, 1, 1), box(1, 1, 2, 2)));      // a shared corner
  EXPECT_FALSE(polygons_overlap(box(0, 0, 1, 1), box(1, 0.2, 2, 0.8)));  // part of an edge
  EXPECT_FALSE(polygons_overlap(box(0, 0, 1, 1), box(3, 0, 4, 1)));      // apart
}

TEST(PolygonsOverlap, CrossingAndContained) {
  EXPECT_TRUE(polygons_overlap(box(0, 0, 2, 2), box(1, 1, 3, 3)));  // edges cross
  EXPECT_TRUE(polygons_overlap(box(0, 0, 4, 4), box(1, 1, 2, 2)));  // inside
  EXPECT_TRUE(polygons_overlap(box(1, 1, 2, 2), box(0, 0, 4, 4)));  // around
  EXPECT_TRUE(polygons_overlap(box(0, 0, 4, 4), box(0, 0, 4, 4)));  // the same
  EXPECT_TRUE(polygons_overlap(box(0, 0, 4, 1), box(0, 0, 1, 1)));  // a corner shared
  // An L and a box in its notch: no overlap; a box over its inner corner: overlap.
  const Polygon2 l = {{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}};
  EXPECT_FALSE(polygons_overlap(l, box(2, 2, 4, 4)));
  EXPECT_TRUE(polygons_overlap(l, box(1.5, 1.5, 3, 3)));
}

}  // namespace
}  // namespace luxgrid::geometry
