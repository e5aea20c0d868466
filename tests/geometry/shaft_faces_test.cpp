// Narrowed shafts (geometry/visibility.h, ShaftFaces): a segment of a shaft answered from the faces
// its classification left undecided must get the occlusion test's answer, the trace through every
// face, for every segment; and a part of an element classified within its whole's faces must keep
// both the verdict's proof and that answer. Checked by brute force in an L-shaped room with three
// obstacles: openings on the ceiling against receivers across the room, each opening split into
// triangles and those again (as the reference's cubature splits it), every segment from sampled
// points of each part to the receiver compared with the trace.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "geometry/occlusion.h"
#include "tests/geometry/l_outline.h"

namespace luxgrid::geometry {
namespace {

using Triangle = std::array<Vec3, 3>;

struct NarrowTally {
  size_t segments = 0, narrowed = 0, faces_left = 0, proofs = 0, hidden_segments = 0;
};

// Every segment from points of `t` (corners, edge points, inner points) to `r`: the answer from
// the faces `left` equals the trace's; where the verdict is a proof, it equals the trace's too.
void check_part(const OcclusionTree& tree, const Triangle& t, const Vec3& r, Shaft verdict,
                const ShaftFaces& left, test::Lcg& rng, NarrowTally& tally,
                const std::string& what) {
  std::vector<Vec3> points(t.begin(), t.end());
  for (int k = 0; k < 3; ++k)
    for (const double s : {0.001, 0.5, 0.999}) points.push_back(t[k] + s * (t[(k + 1) % 3] - t[k]));
  for (int k = 0; k < 12; ++k) {
    double u = rng(), v = rng();
    if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
    points.push_back(t[0] + u * (t[1] - t[0]) + v * (t[2] - t[0]));
  }
  for (const Vec3& p : points) {
    const bool traced = tree.visible(p, r);
    ++tally.segments;
    tally.hidden_segments += traced ? 0 : 1;
    if (verdict != Shaft::partial) {
      ASSERT_EQ(traced, verdict == Shaft::visible) << what;
      continue;
    }
    ASSERT_EQ(tree.visible_among(p, r, left), traced)
        << what << ": (" << p.x << ", " << p.y << ", " << p.z << ")";
  }
  if (verdict != Shaft::partial) ++tally.proofs;
  if (verdict == Shaft::partial && left.narrowed()) {
    ++tally.narrowed;
    tally.faces_left += static_cast<size_t>(left.count);
  }
}

// Classifies `t` within `among`, checks it, and its four midpoint children within what it left,
// down `depth` levels.
void check_tree(const OcclusionTree& tree, const Triangle& t, const Vec3& r,
                const ShaftFaces& among, int depth, test::Lcg& rng, NarrowTally& tally,
                const std::string& what) {
  ShaftFaces left;
  const Shaft verdict = tree.classify_within(t, std::span<const Vec3>(&r, 1), among, left);
  check_part(tree, t, r, verdict, left, rng, tally, what);
  if (verdict != Shaft::partial || depth == 0) return;
  const Vec3 ab = 0.5 * (t[0] + t[1]), bc = 0.5 * (t[1] + t[2]), ca = 0.5 * (t[2] + t[0]);
  for (const Triangle& child : {Triangle{t[0], ab, ca}, Triangle{ab, t[1], bc},
                                Triangle{ca, bc, t[2]}, Triangle{ab, bc, ca}})
    check_tree(tree, child, r, left, depth - 1, rng, tally, what);
}

TEST(ShaftFaces, NarrowedAnswersEqualTheTraceForEverySegment) {
  const std::vector<Face> faces = test::furnished_l_faces();
  const OcclusionTree tree(faces);
  test::Lcg rng;
  NarrowTally tally;
  // 0.6 x 0.6 m openings in the ceiling's plane (and one below it), each as two triangles; the
  // receivers on a lattice of the floor, the desk's and the cabinet's heights, lining up with the
  // reflex corner (3, 3) and the obstacles' edges.
  for (const Vec3& c : {Vec3(1.0, 1.0, 3.0), Vec3(2.5, 5.0, 3.0), Vec3(5.0, 2.5, 3.0),
                        Vec3(3.0, 1.5, 3.0), Vec3(1.5, 3.0, 2.6)}) {
    const Vec3 p0 = c + Vec3(-0.3, -0.3, 0), p1 = c + Vec3(0.3, -0.3, 0),
               p2 = c + Vec3(0.3, 0.3, 0), p3 = c + Vec3(-0.3, 0.3, 0);
    for (int i = 0; i <= 12; ++i)
      for (int j = 0; j <= 12; ++j) {
        const double x = 0.5 * i, y = 0.5 * j;
        if (x > 3 && y > 3) continue;
        for (const double z : {0.0, 0.75, 1.8}) {
          const Vec3 r(x, y, z);
          const std::string what = "opening at " + std::to_string(c.x) + ", " +
                                   std::to_string(c.y) + " to " + std::to_string(x) + ", " +
                                   std::to_string(y) + ", " + std::to_string(z);
          for (const Triangle& t : {Triangle{p0, p1, p2}, Triangle{p0, p2, p3}})
            check_tree(tree, t, r, ShaftFaces{}, 3, rng, tally, what);
        }
      }
  }
  // Not vacuous: many segments hidden, many parts narrowed to a few faces, many proofs.
  EXPECT_GT(tally.hidden_segments, tally.segments / 20) << tally.segments;
  EXPECT_GT(tally.narrowed, 2000u);
  EXPECT_GT(tally.proofs, 2000u);
  EXPECT_LT(tally.faces_left, 4 * tally.narrowed);
}

TEST(ShaftFaces, TooManyFacesLeaveTheShaftUnnarrowed) {
  // A row of thin slats across the room's ceiling: a shaft from a wide opening to the floor meets
  // more of them than ShaftFaces holds, and is then not narrowed (every face stays a candidate),
  // still with the trace's answers.
  auto faces =
      room_faces(RoomShape{"box", {{0, 0}, {8, 0}, {8, 8}, {0, 8}}, 0.0, 3.0, 0.2, 0.5, 0.7});
  for (int k = 0; k < 8; ++k) {
    const double x = 2.0 + 0.5 * k;
    const auto f = obstacle_faces(make_box("slat", {x, 1, 2.0}, {x + 0.05, 7, 2.2}, 0.0, 0.5));
    faces.insert(faces.end(), f.begin(), f.end());
  }
  const OcclusionTree tree(faces);
  const std::vector<Vec3> opening = {{1, 3, 3}, {7, 3, 3}, {7, 5, 3}, {1, 5, 3}};
  const Vec3 r(4.0, 4.0, 0.0);
  ShaftFaces left;
  ASSERT_EQ(tree.classify_within(opening, std::span<const Vec3>(&r, 1), ShaftFaces{}, left),
            Shaft::partial);
  EXPECT_FALSE(left.narrowed());
  test::Lcg rng;
  size_t hidden = 0;
  for (int k = 0; k < 400; ++k) {
    const Vec3 p(1.0 + 6.0 * rng(), 3.0 + 2.0 * rng(), 3.0);
    const bool traced = tree.visible(p, r);
    hidden += traced ? 0 : 1;
    ASSERT_EQ(tree.visible_among(p, r, left), traced);
  }
  EXPECT_GT(hidden, 40u);
  EXPECT_LT(hidden, 360u);
}

}  // namespace
}  // namespace luxgrid::geometry
