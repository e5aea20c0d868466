// Workplanes over non-convex rooms: the inset (arcs at reflex corners), grid positions at cell
// centres, and the points left out (outside the inset outline, inside obstacles) against
// hand-counted grids. Auto spacing against the EN 12464-1 formula on worked examples.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/workplane.h"
#include "tests/geometry/l_outline.h"

namespace luxgrid::geometry {
namespace {

using test::kL;
const Polygon2 kU = {{0, 0}, {5, 0}, {5, 4}, {4, 4}, {4, 1}, {1, 1}, {1, 4}, {0, 4}};

size_t active_count(const SurfaceGrid& g) {
  size_t n = 0;
  for (bool a : g.active) n += a;
  return n;
}

TEST(Inset, LShapeByHalfAMetre) {
  const auto inset = inset_region(kL, 0.5);
  ASSERT_EQ(inset.polygons.size(), 1u);
  EXPECT_EQ(inset.walls, &kL);  // a reflex corner: points are decided by their distance
  const Polygon2& region = inset.polygons[0];
  // The walls moved in by 0.5 m meet at the convex corners, exact after snapping; at the reflex
  // corner (3, 3) an arc of radius 0.5 from (3, 2.5) to (2.5, 3) replaces the mitre (2.5, 2.5).
  for (const Vec2& p : {Vec2(0.5, 0.5), Vec2(5.5, 0.5), Vec2(5.5, 2.5), Vec2(3, 2.5), Vec2(2.5, 3),
                        Vec2(2.5, 5.5), Vec2(0.5, 5.5)}) {
    bool found = false;
    for (const auto& q : region) found = found || q == p;
    EXPECT_TRUE(found) << p.x << ", " << p.y;
  }
  for (const auto& q : region) {
    if (q.x > 2.5 && q.y > 2.5) {
      EXPECT_NEAR(glm::length(q - Vec2(3, 3)), 0.5, 1e-12);
    }
  }
  // The mitred L's 16 m^2, plus the corner square's part outside the disc, 0.25 (1 - pi / 4),
  // plus the 18 circular segments between the 5-degree chords and the arc, each
  // 0.25 / 2 (theta - sin theta).
  const double theta = kPi / 36.0;
  EXPECT_NEAR(signed_area(region),
              16.0 + 0.25 * (1.0 - kPi / 4.0) + 18 * 0.125 * (theta - std::sin(theta)), 1e-12);
  // A convex outline keeps the straight skeleton's polygon and its polygon test.
  const Polygon2 rectangle = {{0, 0}, {4, 0}, {4, 3}, {0, 3}};
  EXPECT_EQ(inset_region(rectangle, 0.5).walls, nullptr);
}

TEST(Inset, TooWideABorderLeavesNothing) {
  // The U's arms and base are 1 m wide: a 0.6 m border eats them all.
  EXPECT_TRUE(inset_outline(kU, 0.6).empty());
  EXPECT_EQ(inset_outline(kU, 0.0).size(), 1u);
}

TEST(Workplane, LShapeOneMetreGridHandCounted) {
  // Inset L spans 0.5..5.5 in x and y: 5 x 5 cells of 1 m, centres at 1, 2, 3, 4, 5.
  // Rows y = 1, 2 lie in the lower arm (all 5 points); rows y = 3, 4, 5 only at x = 1, 2.
  const auto g = make_region_grid("wp", inset_region(kL, 0.5), 0.8, 1.0, {});
  EXPECT_EQ(g.nu, 5);
  EXPECT_EQ(g.nv, 5);
  EXPECT_EQ(g.points.front(), Vec3(1, 1, 0.8));
  EXPECT_EQ(g.points.back(), Vec3(5, 5, 0.8));
  EXPECT_EQ(active_count(g), 16u);
  EXPECT_EQ(g.points_outside, 9u);
  EXPECT_EQ(g.points_in_obstacles, 0u);
  const auto at = [&](int i, int j) { return g.active[static_cast<size_t>(j * g.nu + i)]; };
  EXPECT_TRUE(at(4, 1));   // (5, 2)
  EXPECT_FALSE(at(2, 2));  // (3, 3): in the missing quadrant
  EXPECT_TRUE(at(1, 4));   // (2, 5)
  EXPECT_FALSE(at(2, 4));  // (3, 5)
  for (const auto& n : g.normals) EXPECT_EQ(n, Vec3(0, 0, 1));
}

TEST(Workplane, LShapeUnevenSpacingHandCounted) {
  // 5 m / 0.4 m = 12.5 -> 13 cells of 5/13 m. Centres x_i = 0.5 + (i + 0.5) 5/13.
  // Lower arm (y <= 2.5): j + 0.5 <= 5.2 -> j = 0..4, 5 rows x 13 = 65.
  // Upper arm (x <= 2.5): i = 0..4, 8 rows x 5 = 40. And (i, j) = (5, 5), at x = y = 2.615,
  // beyond both arms but 0.544 m from the reflex corner (3, 3), its nearest wall point: the
  // mitred corner at (2.5, 2.5) left it out, the border does not. Active 106 of 169.
  const auto g = make_region_grid("wp", inset_region(kL, 0.5), 0.8, 0.4, {});
  EXPECT_EQ(g.nu, 13);
  EXPECT_EQ(g.nv, 13);
  EXPECT_DOUBLE_EQ(g.spacing_u, 5.0 / 13.0);
  EXPECT_EQ(active_count(g), 106u);
  EXPECT_EQ(g.points_outside, 63u);
  EXPECT_TRUE(g.active[5 * 13 + 5]);
  EXPECT_FALSE(g.active[5 * 13 + 6]);  // (3.0, 2.615): 0.385 m from the wall x = 3
}

TEST(Workplane, UShapeQuarterMetreBorderHandCounted) {
  // Inset U: 0.25..4.75 x 0.25..3.75 minus the notch 0.75..4.25 x 0.75..3.75 (the base and
  // arms are 1 m wide, so 0.5 m of each is left). 0.5 m cells: 9 x 7, centres x = 0.5..4.5,
  // y = 0.5..3.5. Row y = 0.5: all 9; rows y = 1.0..3.5 (6 rows): x = 0.5 and 4.5 only.
  // 9 + 12 = 21 active, 63 - 21 = 42 outside.
  const auto g = make_region_grid("wp", inset_region(kU, 0.25), 0.8, 0.5, {});
  EXPECT_EQ(g.nu, 9);
  EXPECT_EQ(g.nv, 7);
  EXPECT_EQ(g.points.front(), Vec3(0.5, 0.5, 0.8));
  EXPECT_EQ(active_count(g), 21u);
  EXPECT_EQ(g.points_outside, 42u);
  EXPECT_TRUE(g.active[0 * 9 + 4]);   // (2.5, 0.5): in the base
  EXPECT_FALSE(g.active[1 * 9 + 4]);  // (2.5, 1.0): in the notch
  EXPECT_TRUE(g.active[6 * 9 + 8]);   // (4.5, 3.5): top of the right arm
}

TEST(Workplane, ChamferedCornerHandCounted) {
  // A 4 x 4 room with its north-east corner cut at 45 degrees: the chamfer x + y = 6 moves in by
  // the border along its normal, to x + y = 6 - 0.5 sqrt(2) = 5.2929. Inset box 0.5..3.5, 0.5 m
  // cells: 6 x 6, centres 0.75 + 0.5 i. A centre is outside when 1.5 + 0.5 (i + j) > 5.2929,
  // i.e. i + j >= 8: (3,5), (4,4), (5,3), (4,5), (5,4), (5,5) -> 6 outside, 30 active (the
  // nearest centres, i + j = 7, sit 0.21 m inside the chamfer: no ties).
  const Polygon2 chamfered = {{0, 0}, {4, 0}, {4, 2}, {2, 4}, {0, 4}};
  const auto region = inset_outline(chamfered, 0.5);
  ASSERT_EQ(region.size(), 1u);
  EXPECT_NEAR(signed_area(region[0]),
              9.0 - 0.5 * std::pow(3.5 + 3.5 - (6.0 - 0.5 * std::sqrt(2.0)), 2), 1e-9);
  const auto g = make_region_grid("wp", region, 0.8, 0.5, {});
  EXPECT_EQ(g.nu, 6);
  EXPECT_EQ(g.nv, 6);
  EXPECT_EQ(g.points.front(), Vec3(0.75, 0.75, 0.8));
  EXPECT_EQ(active_count(g), 30u);
  EXPECT_EQ(g.points_outside, 6u);
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i)
      EXPECT_EQ(g.active[static_cast<size_t>(j * 6 + i)], i + j < 8) << i << ", " << j;
}

TEST(Workplane, ObstaclesSpanningTheHeightRemovePoints) {
  // A column over (2, 2) removes that point; a 0.7 m table under (1, 1) does not (the
  // workplane at 0.8 m passes over it); a box through (1, 2) in the air above 1 m does not.
  const std::vector<Obstacle> obstacles = {
      make_box("column", {1.5, 1.5, 0}, {2.5, 2.5, 3}, 0.0, 0.5),
      make_box("table", {0.6, 0.6, 0}, {1.4, 1.4, 0.7}, 0.0, 0.5),
      make_box("shelf", {0.6, 1.6, 1.0}, {1.4, 2.4, 1.2}, 0.0, 0.5)};
  const auto g = make_region_grid("wp", inset_region(kL, 0.5), 0.8, 1.0, obstacles);
  EXPECT_EQ(active_count(g), 15u);
  EXPECT_EQ(g.points_in_obstacles, 1u);
  EXPECT_EQ(g.points_outside, 9u);
  EXPECT_FALSE(g.active[1 * 5 + 1]);  // (2, 2)
}

TEST(Workplane, RectangleMatchesPlaneGridExactly) {
  // The old rectangular path: 4 x 3 room, border 0.5 -> 6 x 4 cells at 0.5 m from (0.75, 0.75).
  const auto g =
      make_region_grid("wp", inset_outline({{0, 0}, {4, 0}, {4, 3}, {0, 3}}, 0.5), 0.8, 0.5, {});
  EXPECT_EQ(g.nu, 6);
  EXPECT_EQ(g.nv, 4);
  EXPECT_EQ(g.points.front(), Vec3(0.75, 0.75, 0.8));
  EXPECT_EQ(g.points.back(), Vec3(3.25, 2.25, 0.8));
  EXPECT_EQ(active_count(g), 24u);
}

TEST(AutoSpacing, WorkedExamples) {
  // EN 12464-1: p = 0.2 * 5^log10(d). d = 1 m -> 0.2 m; 10 m -> 1 m; 100 m -> 5 m.
  EXPECT_NEAR(auto_spacing(1.0), 0.2, 1e-15);
  EXPECT_NEAR(auto_spacing(10.0), 1.0, 1e-15);
  EXPECT_NEAR(auto_spacing(100.0), 5.0, 1e-14);
  // A second form of the same rule: 5^log10(d) = d^log10(5).
  for (double d : {0.5, 4.0, 6.0, 20.0, 50.0}) {
    EXPECT_NEAR(auto_spacing(d), 0.2 * std::pow(d, std::log10(5.0)), 1e-12) << d;
  }
  EXPECT_NEAR(auto_spacing(50.0), 3.0800592217225153, 1e-12);
  // The cap: p never exceeds 10 m (reached at d = 10^(log(50)/log(5)) ~ 1151 m).
  EXPECT_EQ(auto_spacing(1e6), 10.0);
}

TEST(AutoSpacing, LWorkplaneUsesTheLongerSideOfItsBoundingBox) {
  // Inset L: 5 x 5 m box -> p = 0.2 * 5^log10(5) = 0.6141 m -> ceil(5 / 0.6141) = 9 cells.
  const auto region = inset_outline(kL, 0.5);
  const double p = auto_spacing(bounds(region).longer_side());
  EXPECT_NEAR(p, 0.2 * std::pow(5.0, std::log10(5.0)), 1e-15);
  const auto g = make_region_grid("wp", region, 0.8, p, {});
  EXPECT_EQ(g.nu, 9);
  EXPECT_EQ(g.nv, 9);
}

TEST(RoomSurfaces, LRoomGridsCoverEveryFace) {
  const RoomShape room{"L", kL, 0.0, 3.0, 0.2, 0.5, 0.7};
  const auto grids = make_room_surface_grids("L", room, 1.0, {});
  ASSERT_EQ(grids.size(), 8u);
  EXPECT_EQ(grids[0].name, "L floor");
  EXPECT_EQ(active_count(grids[0]), 27u);  // 27 m^2 at 1 m: 27 whole cells inside
  EXPECT_EQ(grids[1].name, "L ceiling");
  EXPECT_EQ(grids[1].normals[0], Vec3(0, 0, -1));
  EXPECT_EQ(active_count(grids[1]), 27u);
  // Wall 0 along y = 0, 6 x 3 cells, normal into the room (+y), points on the wall.
  EXPECT_EQ(grids[2].name, "L wall 0");
  EXPECT_EQ(grids[2].nu, 6);
  EXPECT_EQ(grids[2].nv, 3);
  EXPECT_EQ(grids[2].normals[0], Vec3(0, 1, 0));
  EXPECT_EQ(grids[2].points[0].y, 0.0);
  // Wall 3 from (3,3) to (3,6): normal -x.
  EXPECT_EQ(grids[5].normals[0], Vec3(-1, 0, 0));
  EXPECT_EQ(grids[5].points[0].x, 3.0);
}

}  // namespace
}  // namespace luxgrid::geometry
