// Prisms that meet and the union of overlapping obstacles (geometry/prism_union.h): each expected
// footprint is written by hand from the drawing of the two boxes; contacts are decided exactly, so
// a box touching another only along an edge or at a corner is apart.
#include <gtest/gtest.h>

#include "geometry/prism_union.h"

namespace luxgrid::geometry {
namespace {

Polygon2 rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

Obstacle box(const std::string& name, const Polygon2& footprint, double z0, double z1,
             double rho = 0.5) {
  return {name, footprint, z0, z1, rho};
}

TEST(PrismContact, ClassifiesEachWayTwoPrismsMeet) {
  const Polygon2 a = rect(0, 0, 1, 1);
  EXPECT_EQ(prism_contact(a, 0, 1, rect(0.5, 0, 1.5, 1), 0, 1), PrismContact::overlap);
  EXPECT_EQ(prism_contact(a, 0, 1, rect(1, 0.2, 2, 0.8), 0, 1), PrismContact::share_face);
  EXPECT_EQ(prism_contact(a, 0, 1, rect(0.2, 0.2, 0.8, 0.8), 1, 2), PrismContact::share_face);
  EXPECT_EQ(prism_contact(a, 0, 1, rect(1, 1, 2, 2), 0, 1), PrismContact::apart);  // corner
  EXPECT_EQ(prism_contact(a, 0, 1, rect(0, 0, 1, 1), 1.5, 2), PrismContact::apart);
  EXPECT_EQ(prism_contact(a, 0, 1, rect(1.25, 0, 2, 1), 0, 1), PrismContact::apart);
  // A 1e-12 m overlap is an overlap: the test is exact, not within a tolerance.
  EXPECT_EQ(prism_contact(a, 0, 1, rect(1 - 1e-12, 0, 2, 1), 0, 1), PrismContact::overlap);
}

TEST(UniteObstacles, ObstaclesThatMeetNothingAreKeptAsGiven) {
  const std::vector<Obstacle> in = {box("a", rect(0, 0, 1, 1), 0, 1),
                                    box("b", rect(2, 0, 3, 1), 0, 2)};
  const ObstacleUnion u = unite_obstacles(in);
  ASSERT_FALSE(u.conflict);
  ASSERT_EQ(u.obstacles.size(), 2u);
  EXPECT_EQ(u.obstacles[1].footprint, in[1].footprint);
  EXPECT_EQ(u.members[1], std::vector<size_t>{1});
}

TEST(UniteObstacles, TheSameBoxTwiceIsOneBox) {
  const std::vector<Obstacle> in = {box("a", rect(0, 0, 1, 1), 0, 1),
                                    box("b", rect(0, 0, 1, 1), 0, 1)};
  const ObstacleUnion u = unite_obstacles(in);
  ASSERT_FALSE(u.conflict);
  ASSERT_EQ(u.obstacles.size(), 1u);
  EXPECT_EQ(u.obstacles[0].name, "a");
  EXPECT_EQ(u.obstacles[0].footprint, in[0].footprint);
  EXPECT_EQ(u.members[0], (std::vector<size_t>{0, 1}));
}

TEST(UniteObstacles, StackedBoxesOnOneFootprintJoinTheirHeights) {
  const ObstacleUnion u =
      unite_obstacles({box("low", rect(0, 0, 1, 1), 0, 1), box("high", rect(0, 0, 1, 1), 1, 2.5)});
  ASSERT_EQ(u.obstacles.size(), 1u);
  EXPECT_EQ(u.obstacles[0].z0, 0.0);
  EXPECT_EQ(u.obstacles[0].z1, 2.5);
}

TEST(UniteObstacles, OverlappingBoxesBecomeTheOutlineOfTheirUnion) {
  // Two 1 x 1 boxes overlapping by half, and a third touching the second's right side: a 2.5 x 1
  // rectangle with no corner left on its straight sides.
  const ObstacleUnion u =
      unite_obstacles({box("a", rect(0, 0, 1, 1), 0, 1), box("b", rect(0.5, 0, 1.5, 1), 0, 1),
                       box("c", rect(1.5, 0, 2.5, 1), 0, 1)});
  ASSERT_FALSE(u.conflict);
  ASSERT_EQ(u.obstacles.size(), 1u);
  EXPECT_EQ(u.obstacles[0].footprint, rect(0, 0, 2.5, 1));
}

TEST(UniteObstacles, CrossedBoxesGiveTheTwelveCornersOfAPlusSign) {
  const ObstacleUnion u =
      unite_obstacles({box("a", rect(0, 1, 3, 2), 0, 1), box("b", rect(1, 0, 2, 3), 0, 1)});
  ASSERT_EQ(u.obstacles.size(), 1u);
  const Polygon2 plus = {{0, 1}, {1, 1}, {1, 0}, {2, 0}, {2, 1}, {3, 1},
                         {3, 2}, {2, 2}, {2, 3}, {1, 3}, {1, 2}, {0, 2}};
  EXPECT_EQ(u.obstacles[0].footprint, plus);
}

TEST(UniteObstacles, WhatIsNoPrismIsAConflictNamingTheFirstPairThatMeets) {
  // Different heights overlapping: the union is no prism.
  ObstacleUnion u =
      unite_obstacles({box("free", rect(5, 5, 6, 6), 0, 1), box("desk", rect(0, 0, 2, 1), 0, 0.75),
                       box("column", rect(1.5, 0.5, 2, 1.2), 0, 3)});
  ASSERT_TRUE(u.conflict);
  EXPECT_EQ(u.conflict->first, 1u);
  EXPECT_EQ(u.conflict->second, 2u);
  EXPECT_EQ(u.conflict->contact, PrismContact::overlap);
  EXPECT_TRUE(u.obstacles.empty());
  // Different reflectances pressed together.
  u = unite_obstacles(
      {box("a", rect(0, 0, 1, 1), 0, 1, 0.5), box("b", rect(1, 0, 2, 1), 0, 1, 0.8)});
  ASSERT_TRUE(u.conflict);
  EXPECT_EQ(u.conflict->contact, PrismContact::share_face);
  // A ring of four boxes around a hole.
  u = unite_obstacles({box("s", rect(0, 0, 3, 1), 0, 1), box("e", rect(2, 0, 3, 3), 0, 1),
                       box("n", rect(0, 2, 3, 3), 0, 1), box("w", rect(0, 0, 1, 3), 0, 1)});
  ASSERT_TRUE(u.conflict);
}

}  // namespace
}  // namespace luxgrid::geometry
