// The part of an outline at least a border from every wall (geometry/wall_clearance.h): each
// corner of the region's polygons lies at exactly the border from its nearest wall (an invariant
// of the erosion's boundary, checked by brute force over all walls), areas against closed forms,
// and the shapes where a mitred offset goes wrong (a thin spike, a star, a narrow passage).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geometry/wall_clearance.h"

namespace luxgrid::geometry {
namespace {

double nearest_wall_m(const Vec2& p, const Polygon2& poly) {
  double d = INFINITY;
  for (size_t k = 0; k < poly.size(); ++k)
    d = std::min(d, distance_to_segment(p, poly[k], poly[(k + 1) % poly.size()]));
  return d;
}

// Every corner of every polygon at the border from the walls (1e-9 m: the rounding of the
// crossings), and inside the outline.
void expect_on_the_border(const std::vector<Polygon2>& region, const Polygon2& outline,
                          double border_m) {
  for (const auto& poly : region) {
    for (const auto& q : poly) {
      EXPECT_NEAR(nearest_wall_m(q, outline), border_m, 1e-9) << q.x << ", " << q.y;
      EXPECT_NE(locate(q, outline, 0.0), Location::outside);
    }
  }
}

TEST(WallClearance, SquareIsTheSmallerSquare) {
  const Polygon2 square = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  const auto region = wall_clearance_region(square, 0.5);
  ASSERT_EQ(region.size(), 1u);
  EXPECT_EQ(region[0].size(), 4u);
  EXPECT_NEAR(signed_area(region[0]), 9.0, 1e-12);
  expect_on_the_border(region, square, 0.5);
}

TEST(WallClearance, ThinSpikeRemovesOnlyABandAroundIt) {
  // A 6 x 4 m room with a 2 cm wide spike 1 m into it from the north wall (tip (3, 3)). The
  // region is the room less a 0.3 m band along the walls and around the spike: its area is the
  // inner 5.4 x 3.4 rectangle less the spike's band inside it. The point under the middle of
  // the room, 1 m from the tip, stays (a mitred tip would have shot through it).
  const Polygon2 room = {{0, 0}, {6, 0}, {6, 4}, {3.01, 4}, {3, 3}, {2.99, 4}, {0, 4}};
  const auto region = wall_clearance_region(room, 0.3);
  ASSERT_EQ(region.size(), 1u);
  expect_on_the_border(region, room, 0.3);
  EXPECT_TRUE(clear_of_walls({3, 2}, room, 0.3));
  EXPECT_EQ(locate({3, 2}, region[0], 0.0), Location::inside);
  EXPECT_FALSE(clear_of_walls({3, 2.75}, room, 0.3));  // 0.25 m below the tip
  EXPECT_TRUE(clear_of_walls({3, 2.69}, room, 0.3));   // 0.31 m below it
  // Within the inner rectangle's 18.36 m^2 the spike takes at most its band: a 0.62 m wide
  // strip from the tip's half disc up to y = 3.7, 0.62 x 0.7 + pi 0.3^2 / 2 = 0.575 m^2.
  EXPECT_GT(signed_area(region[0]), 18.36 - 0.58);
  EXPECT_LT(signed_area(region[0]), 18.36 - 0.5);
}

TEST(WallClearance, StarKeepsItsCentre) {
  // A five-pointed star, points 3 m and inner corners 0.5 m from its centre: each wall's nearest
  // point to the centre is an inner corner (the foot of the perpendicular on a wall's line falls
  // beyond it), so the centre is 0.5 m from every wall, and a 1 cm border leaves it 0.49 m clear.
  Polygon2 star;
  for (int k = 0; k < 10; ++k) {
    const double r = k % 2 ? 0.5 : 3.0, a = kPi * k / 5;
    star.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  EXPECT_NEAR(nearest_wall_m({0, 0}, star), 0.5, 1e-9);
  const auto region = wall_clearance_region(star, 0.01);
  ASSERT_EQ(region.size(), 1u);
  expect_on_the_border(region, star, 0.01);
  EXPECT_EQ(locate({0, 0}, region[0], 0.0), Location::inside);
  EXPECT_TRUE(clear_of_walls({0, 0}, star, 0.5));
  EXPECT_FALSE(clear_of_walls({0, 0}, star, 0.51));
  EXPECT_TRUE(wall_clearance_region(star, 0.51).empty());
}

TEST(WallClearance, NarrowPassageSplitsTheRegion) {
  // Two 3 x 3 m halls joined by a 0.4 m wide passage: a 0.3 m border leaves in each hall its
  // 2.4 x 2.4 m square and, at the passage's mouth, part of the 0.3 x 0.4 m strip beyond it
  // (clear of the mouth's corners by 0.3 m), nothing of the passage itself.
  const Polygon2 dumbbell = {{0, 0}, {3, 0}, {3, 1.3}, {4, 1.3}, {4, 0}, {7, 0},
                             {7, 3}, {4, 3}, {4, 1.7}, {3, 1.7}, {3, 3}, {0, 3}};
  const auto region = wall_clearance_region(dumbbell, 0.3);
  ASSERT_EQ(region.size(), 2u);
  expect_on_the_border(region, dumbbell, 0.3);
  for (const auto& poly : region) {
    EXPECT_GT(signed_area(poly), 2.4 * 2.4);
    EXPECT_LT(signed_area(poly), 2.4 * 2.4 + 0.3 * 0.4);
  }
  // A 0.15 m border keeps the passage (0.1 m wide in the middle): one region.
  EXPECT_EQ(wall_clearance_region(dumbbell, 0.15).size(), 1u);
}

TEST(WallClearance, PointsOnTheBorderLineCount) {
  const Polygon2 l_room = {{0, 0}, {6, 0}, {6, 3}, {3, 3}, {3, 6}, {0, 6}};
  EXPECT_TRUE(clear_of_walls({0.5, 1.0}, l_room, 0.5));                // exactly 0.5 m
  EXPECT_TRUE(clear_of_walls({0.5 - 0.9e-9, 1.0}, l_room, 0.5));       // within 1 nm
  EXPECT_FALSE(clear_of_walls({0.5 - 2e-9, 1.0}, l_room, 0.5));        // beyond it
  EXPECT_TRUE(clear_of_walls({3.0 - 0.3, 3.0 - 0.4}, l_room, 0.5));    // 0.5 m from (3, 3)
  EXPECT_FALSE(clear_of_walls({3.0 - 0.3, 3.0 - 0.39}, l_room, 0.5));  // 0.492 m from it
}

}  // namespace
}  // namespace luxgrid::geometry
