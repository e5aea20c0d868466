// The CGAL-free part of geometry that the hot paths share: the visibility interface and its
// obstacle-box filter (visibility.h), the closest point of a polygon and the horizon clip
// (polygon3.h), Lambert's projected solid angle (spherical.h).
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/polygon3.h"
#include "geometry/spherical.h"
#include "geometry/visibility.h"

namespace luxgrid::geometry {
namespace {

// Blocks every segment: whatever the filter passes on is blocked.
class Wall final : public Visibility {
 public:
  bool visible(const Vec3&, const Vec3&) const override { return false; }
};

TEST(VisibilityInterface, NullBlocksNothing) {
  EXPECT_FALSE(blocked(nullptr, Vec3(0.0), Vec3(1.0)));
}

TEST(VisibilityInterface, BoxFilterAsksTheExactTestOnlyForSegmentsMeetingABox) {
  const Wall wall;
  const BoxFilteredVisibility filtered(wall, {Box3{Vec3(1.0, 1.0, 0.0), Vec3(2.0, 2.0, 1.0)}});
  EXPECT_TRUE(filtered.visible(Vec3(0.0, 0.0, 0.5), Vec3(3.0, 0.0, 0.5)));  // passes beside the box
  EXPECT_FALSE(filtered.visible(Vec3(0.0, 0.0, 0.5), Vec3(3.0, 3.0, 0.5)));  // through it
  EXPECT_FALSE(filtered.visible(Vec3(1.5, 1.5, 2.0), Vec3(1.5, 1.5, 1.0)));  // ends on its top
  EXPECT_TRUE(filtered.visible(Vec3(1.5, 1.5, 3.0), Vec3(1.5, 1.5, 2.0)));   // above it
  EXPECT_TRUE(blocked(&filtered, Vec3(0.0, 0.0, 0.5), Vec3(3.0, 3.0, 0.5)));
}

FixedPolygon3<8> unit_square() {
  FixedPolygon3<8> p;
  for (const Vec3& v : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}) p.v[p.n++] = v;
  return p;
}

TEST(Polygon3, ClosestPointInsideOnAnEdgeAndAtACorner) {
  const auto sq = unit_square();
  const Vec3 up(0, 0, 1);
  EXPECT_TRUE(closest_point(sq, Vec3(0.3, 0.6, 0), up).inside);
  const ClosestPoint edge = closest_point(sq, Vec3(2.0, 0.25, 0), up);
  EXPECT_FALSE(edge.inside);
  EXPECT_EQ(edge.edge, 1);
  EXPECT_DOUBLE_EQ(edge.t, 0.25);
  EXPECT_EQ(edge.point, Vec3(1.0, 0.25, 0.0));
  EXPECT_EQ(closest_point(sq, Vec3(2.0, 3.0, 0), up).point, Vec3(1.0, 1.0, 0.0));
}

TEST(Polygon3, HalfSpaceClipOnTheFixedAndTheHeapContainerAgree) {
  // The square clipped to x >= 0.25: a rectangle 0.75 x 1, one corner more than the cut adds.
  const auto sq = unit_square();
  const Vec3 origin(0.25, 0.0, 0.0), n(1.0, 0.0, 0.0);
  const auto fixed = clip_to_half_space_relative<8>(sq.v.data(), sq.n, origin, n);
  const Polygon3 heap = clip_to_half_space(Polygon3(sq.v.begin(), sq.v.begin() + sq.n), origin, n);
  ASSERT_EQ(fixed.n, 4);
  ASSERT_EQ(heap.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(fixed.v[i] + origin, heap[i]) << i;
  EXPECT_NEAR(glm::length(area_vector(heap)), 0.75, 1e-15);
}

TEST(Spherical, ProjectedSolidAngleOfADiskIsPiASquaredOverASquaredPlusHSquared) {
  // A disk of radius a at height h on the axis of the receiver: pi a^2 / (a^2 + h^2) (Lambert).
  // The regular N-gon with the disk's area stands in for it; its error falls as 1 / N^4 (4e-10
  // relative at N = 256, 8e-14 at N = 2048, computed independently in Python while writing
  // this test), so 1e-8 leaves room for rounding only.
  const double a = 0.8, h = 1.3;
  const int N = 256;
  const double R = a * std::sqrt(2.0 * kPi / (N * std::sin(2.0 * kPi / N)));  // equal area
  std::vector<Vec3> rel(N);
  for (int k = 0; k < N; ++k)
    rel[k] = Vec3(R * std::cos(2.0 * kPi * k / N), R * std::sin(2.0 * kPi * k / N), h);
  const double exact = kPi * a * a / (a * a + h * h);
  EXPECT_NEAR(projected_solid_angle(rel.data(), rel.size(), Vec3(0, 0, 1)), exact, 1e-8 * exact);
}

}  // namespace
}  // namespace luxgrid::geometry
