// The AABB occlusion tree: walls of a non-convex room and obstacles block segments; the faces a
// segment starts or ends on do not.
#include <gtest/gtest.h>

#include "geometry/occlusion.h"
#include "tests/geometry/l_outline.h"

namespace luxgrid::geometry {
namespace {

using test::kL;

std::vector<Face> l_room(const std::vector<Obstacle>& obstacles = {}) {
  auto faces = room_faces(RoomShape{"L", kL, 0.0, 3.0, 0.2, 0.5, 0.7});
  for (const auto& o : obstacles) {
    const auto f = obstacle_faces(o);
    faces.insert(faces.end(), f.begin(), f.end());
  }
  return faces;
}

TEST(Occlusion, InnerCornerOfAnLHidesTheOtherLeg) {
  const OcclusionTree tree(l_room());
  EXPECT_EQ(tree.triangle_count(), 2u * 4u + 6u * 2u);  // floor, ceiling: 4 each; walls: 2 each
  const Vec3 lamp(1.0, 5.0, 3.0);                       // on the ceiling of the upper leg
  EXPECT_TRUE(tree.visible(lamp, Vec3(1, 1, 0)));       // straight down the leg
  EXPECT_TRUE(tree.visible(lamp, Vec3(2.5, 1, 0)));     // round the corner but in sight
  EXPECT_FALSE(tree.visible(lamp, Vec3(5.5, 0.5, 0)));  // behind the inner corner
  EXPECT_FALSE(tree.visible(lamp, Vec3(5.5, 2.5, 0.8)));
  // Order does not matter.
  EXPECT_FALSE(tree.visible(Vec3(5.5, 2.5, 0.8), lamp));
}

TEST(Occlusion, PointsOnFacesSeeTheLamp) {
  const OcclusionTree tree(l_room());
  const Vec3 lamp(1.5, 1.5, 3.0);
  EXPECT_TRUE(tree.visible(lamp, Vec3(6.0, 1.5, 1.0)));  // on wall 1
  EXPECT_TRUE(tree.visible(lamp, Vec3(2.0, 0.0, 2.0)));  // on wall 0
  EXPECT_TRUE(tree.visible(lamp, Vec3(4.0, 2.0, 0.0)));  // on the floor
  // A point on the outside face of wall 3 is behind it.
  EXPECT_FALSE(tree.visible(Vec3(1.5, 4.5, 2.0), Vec3(4.0, 4.5, 1.0)));
}

TEST(Occlusion, BoxBetweenLampAndPointBlocks) {
  const OcclusionTree tree(l_room({make_box("cabinet", {1, 1, 0}, {2, 2, 1.8}, 0.0, 0.4)}));
  const Vec3 lamp(1.5, 1.5, 3.0);
  EXPECT_FALSE(tree.visible(lamp, Vec3(1.5, 1.5, 0.0)));  // straight through the box
  EXPECT_TRUE(tree.visible(lamp, Vec3(1.5, 1.5, 1.8)));   // on its top
  // Over its edge: the segment to (1.5, 0.2, 0) crosses y = 1 at z = 3 - 3 * 0.5 / 1.3 = 1.85.
  EXPECT_TRUE(tree.visible(lamp, Vec3(1.5, 0.2, 0.0)));
  // Through its side: to (1.5, 0.5, 0) it crosses y = 1 at z = 1.5 < 1.8.
  EXPECT_FALSE(tree.visible(lamp, Vec3(1.5, 0.5, 0.0)));
  // Grazing past the side: the line from (1.5,1.5,3) to (2.6,1.5,0) is at x = 2.0 at
  // z = 3 - 3 * 0.5 / 1.1 = 1.636 < 1.8: it clips the top edge region and is blocked.
  EXPECT_FALSE(tree.visible(lamp, Vec3(2.6, 1.5, 0.0)));
  // Steeper: at x = 2 the segment to (3.5, 1.5, 0) is at z = 3 - 3 * 0.5 / 2 = 2.25 > 1.8: free.
  EXPECT_TRUE(tree.visible(lamp, Vec3(3.5, 1.5, 0.0)));
}

}  // namespace
}  // namespace luxgrid::geometry
