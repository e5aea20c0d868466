// Faces with holes (geometry/polygon_with_holes.h), checked by invariants that any correct
// triangulation holds: the triangles' areas add up to the outline's area less the holes' (1e-9
// relative: only the rounding of the areas), no triangle's centroid lies in a hole or outside
// the outline (point in polygon), every triangle is counter-clockwise with a positive area, and
// the triangles do not overlap (their areas add up while each lies inside the region).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geometry/polygon_with_holes.h"
#include "tests/geometry/l_outline.h"

namespace luxgrid::geometry {
namespace {

Polygon2 holed_rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

double triangle_area(const HoledTriangulation& t, const std::array<int, 3>& f) {
  return signed_area({t.vertices[f[0]], t.vertices[f[1]], t.vertices[f[2]]});
}

void expect_region(const Polygon2& outline, const std::vector<Polygon2>& holes) {
  const HoledTriangulation t = triangulate_with_holes(outline, holes);
  double expected = signed_area(outline);
  for (const auto& h : holes) expected -= std::abs(signed_area(h));
  double sum = 0.0;
  for (const auto& f : t.triangles) {
    const double a = triangle_area(t, f);
    EXPECT_GT(a, 0.0) << "a triangle turned clockwise or of no area";
    sum += a;
    const Vec2 c = (t.vertices[f[0]] + t.vertices[f[1]] + t.vertices[f[2]]) / 3.0;
    EXPECT_EQ(locate(c, outline, 0.0), Location::inside) << c.x << ", " << c.y;
    for (const auto& h : holes)
      EXPECT_EQ(locate(c, h, 0.0), Location::outside) << "in a hole: " << c.x << ", " << c.y;
  }
  EXPECT_NEAR(sum, expected, 1e-9 * signed_area(outline));
}

TEST(PolygonWithHoles, NoHoleIsTheOutline) {
  expect_region(holed_rect(0, 0, 4, 3), {});
  expect_region(test::kL, {});
}

// A window in a wall (the wall's own coordinates: along it, and height).
TEST(PolygonWithHoles, OneWindowInAWall) {
  expect_region(holed_rect(0, 0, 5, 3), {holed_rect(1, 0.9, 3, 2.1)});
}

// Several openings in one face, one clockwise (either orientation is a hole).
TEST(PolygonWithHoles, SeveralHolesEitherOrientation) {
  Polygon2 cw = holed_rect(3.5, 1, 4.5, 2);
  std::reverse(cw.begin(), cw.end());
  expect_region(holed_rect(0, 0, 6, 3), {holed_rect(0.5, 1, 1.5, 2), holed_rect(2, 1, 3, 2.5), cw});
}

// An opening that touches the face's edge (a door-height window down to the floor), two that
// touch each other along an edge and at a corner, and an opening in a corner of the face.
TEST(PolygonWithHoles, HolesTouchingTheOutlineAndEachOther) {
  expect_region(holed_rect(0, 0, 6, 3), {holed_rect(1, 0, 2, 2.5)});
  expect_region(holed_rect(0, 0, 6, 3),
                {holed_rect(1, 1, 2, 2), holed_rect(2, 1, 3, 2), holed_rect(3, 2, 4, 2.5)});
  expect_region(holed_rect(0, 0, 6, 3), {holed_rect(0, 0, 1, 1), holed_rect(5, 2, 6, 3)});
}

// An opening filling its face (CIE 171 case 5.11's 4 x 3 m facade opening): nothing is left.
TEST(PolygonWithHoles, AHoleFillingTheFaceLeavesNothing) {
  const HoledTriangulation t =
      triangulate_with_holes(holed_rect(0, 0, 4, 3), {holed_rect(0, 0, 4, 3)});
  EXPECT_TRUE(t.triangles.empty());
  // The same hole with its corners starting elsewhere and an extra corner on an edge.
  const Polygon2 hole = {{4, 3}, {0, 3}, {0, 0}, {2, 0}, {4, 0}};
  EXPECT_TRUE(triangulate_with_holes(holed_rect(0, 0, 4, 3), {hole}).triangles.empty());
}

// Roof lights in an L-shaped ceiling (a non-convex outline), one a non-convex polygon.
TEST(PolygonWithHoles, HolesInANonConvexOutline) {
  const Polygon2 l = test::kL;
  const Polygon2 notch = {{1, 1}, {2, 1}, {2, 2}, {1.5, 1.4}, {1, 2}};
  expect_region(l, {notch});
}

// The vertices are the corners given, in order (so a face's corners keep their 3D positions).
TEST(PolygonWithHoles, VerticesAreTheCornersGiven) {
  const Polygon2 outline = holed_rect(0, 0, 5, 3), hole = holed_rect(1, 1, 2, 2);
  const HoledTriangulation t = triangulate_with_holes(outline, {hole});
  ASSERT_EQ(t.vertices.size(), 8u);
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(t.vertices[k], outline[k]);
    EXPECT_EQ(t.vertices[4 + k], hole[k]);
  }
}

}  // namespace
}  // namespace luxgrid::geometry
