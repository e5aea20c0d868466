// segment_crosses (geometry/face_crossing.h) answers from the outline's box where the hit is well
// clear of it, and asks locate() only near the outline: the answer must be the rule's as locate()
// gives it everywhere. Checked by brute force against the rule written out with locate() alone,
// on rectangles (walls, obstacle sides, a turned obstacle's faces) and an L-shaped ceiling, for
// segments whose hits fall on a lattice across and just beside every edge (within 1e-9 to 1e-6 m,
// both sides) and at random.
#include <gtest/gtest.h>

#include <vector>

#include "geometry/face_crossing.h"
#include "geometry/occlusion.h"
#include "tests/geometry/l_outline.h"

namespace luxgrid::geometry {
namespace {

// The rule with locate() for every hit: segment_crosses as it reads without the box.
bool crosses_by_locate(const FaceSheet& face, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double len = glm::length(d);
  if (!(len > 2.0 * kOcclusionEndAllowance_m)) return false;
  const Vec3 step = d * (kOcclusionEndAllowance_m / len);
  const double da = glm::dot(a + step - face.origin, face.normal);
  const double db = glm::dot(b - step - face.origin, face.normal);
  if (!((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0))) return false;
  if (std::max(std::abs(da), std::abs(db)) <= kGrazing_m) return false;
  const double t = da / (da - db);
  const Vec3 hit = a + step + t * (d - 2.0 * step) - face.origin;
  const Location where =
      locate(Vec2(glm::dot(hit, face.u), glm::dot(hit, face.v)), face.outline, kGrazing_m);
  return where == Location::inside || (face.solid && where == Location::boundary);
}

TEST(FaceCrossing, TheOutlinesBoxGivesLocatesAnswer) {
  std::vector<Face> faces = test::furnished_l_faces();
  const auto turned = obstacle_faces(make_box("shelf", {2, 4, 0}, {4, 4.4, 2}, 0.43, 0.4));
  faces.insert(faces.end(), turned.begin(), turned.end());
  test::Lcg rng;
  size_t crossing = 0, near_edge = 0, rectangles = 0;
  for (const Face& f : faces) {
    const FaceSheet s = face_sheet(f);
    rectangles += s.rectangle ? 1 : 0;
    // Hits in the face's frame: a lattice over the box grown by a third, and points just beside
    // each corner's coordinates (both sides of every edge's line).
    std::vector<Vec2> hits;
    const Vec2 size = s.outline_hi - s.outline_lo;
    for (int i = -4; i <= 16; ++i)
      for (int j = -4; j <= 16; ++j)
        hits.push_back(s.outline_lo + Vec2(i / 12.0 * size.x, j / 12.0 * size.y));
    for (const Vec2& c : s.outline)
      for (const double off : {-1e-6, -3e-9, -2e-9, -1e-9, 0.0, 1e-9, 2e-9, 3e-9, 1e-6})
        for (int k = 0; k < 4; ++k) {
          const Vec2 along(rng() * size.x, rng() * size.y);
          hits.emplace_back(c.x + off, s.outline_lo.y + along.y);
          hits.emplace_back(s.outline_lo.x + along.x, c.y + off);
          near_edge += 2;
        }
    for (const Vec2& h : hits) {
      const Vec3 at = s.origin + h.x * s.u + h.y * s.v;
      // A segment through `at`, tilted at random, from 0.5 to 2 m on either side.
      const Vec3 dir = glm::normalize(s.normal + 0.8 * Vec3(rng() - 0.5, rng() - 0.5, rng() - 0.5));
      const Vec3 a = at - (0.5 + 1.5 * rng()) * dir, b = at + (0.5 + 1.5 * rng()) * dir;
      const bool rule = crosses_by_locate(s, a, b);
      crossing += rule ? 1 : 0;
      ASSERT_EQ(segment_crosses(s, a, b), rule) << "hit (" << h.x << ", " << h.y << ")";
      ASSERT_EQ(segment_crosses(s, b, a), crosses_by_locate(s, b, a));
    }
  }
  // Not vacuous: rectangles and other outlines, hits on both sides.
  EXPECT_GT(rectangles, 20u);
  EXPECT_LT(rectangles, faces.size());
  EXPECT_GT(crossing, 5000u);
  EXPECT_GT(near_edge, 5000u);
}

}  // namespace
}  // namespace luxgrid::geometry
