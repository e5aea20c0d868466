// The AABB occlusion tree: walls of a non-convex room and obstacles block segments; the faces a
// segment starts or ends on do not.
#include <gtest/gtest.h>

#include "geometry/face_crossing.h"
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
  // Behind the inner corner (3, 3, z). (5.5, 0.5, 0) would line up with it exactly: the grazing
  // rule's business (GrazingRuleDecidesMeasureZeroConfigurations).
  EXPECT_FALSE(tree.visible(lamp, Vec3(5.5, 1.0, 0)));
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

// The grazing rule (geometry/face_crossing.h), pinned at the configurations of measure zero that
// regular grids produce.
TEST(Occlusion, GrazingRuleDecidesMeasureZeroConfigurations) {
  const OcclusionTree tree(l_room({make_box("cabinet", {1, 1, 0}, {2, 2, 1.8}, 0.0, 0.4),
                                   make_box("column", {4, 1, 0}, {5, 2, 3}, 0.0, 0.5)}));
  // In a face's plane: along the ceiling and along wall 0 (y = 0), inside the room: visible.
  EXPECT_TRUE(tree.visible(Vec3(0.5, 2.5, 3.0), Vec3(2.5, 5.5, 3.0)));
  EXPECT_TRUE(tree.visible(Vec3(0.5, 0.0, 2.5), Vec3(3.5, 0.0, 2.5)));
  // Through the L's reflex corner edge (3, 3, z) exactly: the walls are only touched, visible.
  EXPECT_TRUE(tree.visible(Vec3(4.0, 2.0, 1.0), Vec3(2.0, 4.0, 1.0)));
  EXPECT_TRUE(tree.visible(Vec3(3.5, 2.0, 2.0), Vec3(2.5, 4.0, 0.0)));
  // 1 cm beside it: through wall 2 (blocked) or inside the room (visible).
  EXPECT_FALSE(tree.visible(Vec3(4.0, 2.01, 1.0), Vec3(2.0, 4.0, 1.0)));
  EXPECT_TRUE(tree.visible(Vec3(4.0, 1.99, 1.0), Vec3(2.0, 4.0, 1.0)));
  // An obstacle is a solid: touching its vertical edge (2, 1, z) from outside blocks, and so does
  // entering through one edge and leaving through the opposite one (through its inside).
  EXPECT_FALSE(tree.visible(Vec3(1.0, 0.0, 1.0), Vec3(3.0, 2.0, 1.0)));
  EXPECT_FALSE(tree.visible(Vec3(0.5, 0.5, 1.0), Vec3(2.5, 2.5, 1.0)));
  // In the ceiling's plane over the column that reaches the ceiling: blocked by the column.
  EXPECT_FALSE(tree.visible(Vec3(3.5, 1.5, 3.0), Vec3(5.5, 1.5, 3.0)));
  // Just under the cabinet's top plane, beside it: visible; 1 mm into its top: blocked.
  EXPECT_TRUE(tree.visible(Vec3(0.5, 2.5, 1.8), Vec3(2.5, 2.5, 1.8)));
  EXPECT_FALSE(tree.visible(Vec3(0.5, 1.5, 1.799), Vec3(2.5, 1.5, 1.799)));
}

// The answer is the rule's, whatever the ray tracer's float arithmetic: every face the rule says
// a segment crosses must be found. Segments between points of a 0.25 m lattice (which line up
// with the reflex corner and the obstacles' edges) and random points, against a brute-force loop
// over every face.
TEST(Occlusion, AgreesWithTheRuleOverEveryFace) {
  const auto faces = l_room({make_box("cabinet", {1, 1, 0}, {2, 2, 1.8}, 0.35, 0.4),
                             make_box("column", {4, 1, 0}, {5, 2, 3}, 0.0, 0.5)});
  const OcclusionTree tree(faces);
  std::vector<FaceSheet> sheets;
  for (const auto& f : faces) sheets.push_back(face_sheet(f));
  auto brute = [&](const Vec3& a, const Vec3& b) {
    for (const auto& s : sheets)
      if (segment_crosses(s, a, b)) return false;
    return true;
  };
  std::vector<Vec3> points;
  for (int i = 0; i <= 24; i += 2)
    for (int j = 0; j <= 24; j += 3)
      for (int k = 0; k <= 12; k += 4) points.emplace_back(0.25 * i, 0.25 * j, 0.25 * k);
  uint64_t state = 12345;
  auto uniform = [&]() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  };
  for (int n = 0; n < 300; ++n) points.emplace_back(6 * uniform(), 6 * uniform(), 3 * uniform());
  size_t blocked = 0, grazing = 0;
  for (size_t i = 0; i < points.size(); ++i)
    for (size_t j = i + 1; j < points.size(); j += 7) {
      const bool expected = brute(points[i], points[j]);
      ASSERT_EQ(tree.visible(points[i], points[j]), expected) << i << " " << j;
      blocked += expected ? 0 : 1;
    }
  // The same segments asked from one point at a time in streams of 1 to 16 (visible_from): the
  // same answers, segment by segment.
  std::vector<Vec3> to;
  std::vector<char> expected;
  for (size_t i = 0; i < points.size(); i += 3) {
    to.clear();
    expected.clear();
    for (size_t j = (i * 7) % 11; j < points.size() && to.size() < 1 + i % 16; j += 13) {
      to.push_back(points[j]);
      expected.push_back(brute(points[i], points[j]) ? 1 : 0);
    }
    bool seen[Visibility::kMaxSegmentsFrom];
    tree.visible_from(points[i], to, seen);
    for (size_t k = 0; k < to.size(); ++k) ASSERT_EQ(seen[k], expected[k] != 0) << i << " " << k;
  }
  // Each lattice point and its mirror image about the reflex corner's edge (3, 3, z): the segment
  // between them passes through that edge.
  for (size_t i = 0; i < points.size() - 300; ++i) {
    const Vec3 mirror(6.0 - points[i].x, 6.0 - points[i].y, points[i].z);
    const bool expected = brute(points[i], mirror);
    ASSERT_EQ(tree.visible(points[i], mirror), expected) << i;
    grazing += expected ? 1 : 0;
  }
  EXPECT_GT(blocked, 1000u);  // the comparison is not vacuous
  EXPECT_GT(grazing, 10u);
}

}  // namespace
}  // namespace luxgrid::geometry
