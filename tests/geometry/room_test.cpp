// Rooms and obstacles as faces: outline validation with exact messages, orientation, normals
// into the room, and the triangulation that feeds the AABB tree.
#include <gtest/gtest.h>

#include "geometry/room.h"
#include "tests/geometry/l_outline.h"
#include "util/error.h"

namespace luxgrid::geometry {
namespace {

std::string error_of(Polygon2 outline) {
  try {
    normalize_outline(outline, "room \"L\"");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

using test::kL;

TEST(Outline, CounterClockwiseIsKept) {
  Polygon2 p = kL;
  EXPECT_FALSE(normalize_outline(p, "room \"L\""));
  EXPECT_EQ(p, kL);
}

TEST(Outline, ClockwiseIsReversed) {
  Polygon2 p(kL.rbegin(), kL.rend());
  EXPECT_TRUE(normalize_outline(p, "room \"L\""));
  EXPECT_GT(signed_area(p), 0.0);
  EXPECT_DOUBLE_EQ(signed_area(p), 27.0);
}

TEST(Outline, BadOutlinesHaveExactMessages) {
  EXPECT_EQ(error_of({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {4, 0}}),
            "room \"L\": the outline crosses itself (edge 0-1 meets edge 3-4)");
  // A bow tie: edges 0-1 and 2-3 cross in the middle.
  EXPECT_EQ(error_of({{0, 0}, {4, 4}, {4, 0}, {0, 4}}),
            "room \"L\": the outline crosses itself (edge 0-1 meets edge 2-3)");
  EXPECT_EQ(error_of({{0, 0}, {1, 0}, {2, 0}}), "room \"L\": the outline has zero area");
  EXPECT_EQ(error_of({{0, 0}, {1, 1}}), "room \"L\": an outline needs at least 3 corners, got 2");
  EXPECT_EQ(error_of({{0, 0}, {4, 0}, {4, 0}, {0, 4}}), "room \"L\": corners 1 and 2 coincide");
  // An edge that folds back along the one before it.
  EXPECT_EQ(error_of({{0, 0}, {6, 0}, {4, 0}, {4, 4}, {0, 4}}),
            "room \"L\": the outline crosses itself (edge 0-1 meets edge 1-2)");
  // A thin spike that does not fold back is a legal (simple) outline.
  EXPECT_EQ(error_of({{0, 0}, {4, 0}, {6, 0}, {4, 0.0001}, {4, 4}, {0, 4}}), "(no error)");
  // Touching at a corner (two squares joined at one point) is not simple either.
  EXPECT_EQ(error_of({{0, 0}, {2, 0}, {2, 2}, {4, 2}, {4, 4}, {2, 4}, {2, 2}, {0, 2}}),
            "room \"L\": the outline crosses itself (edge 1-2 meets edge 5-6)");
}

TEST(RoomFaces, LRoomHasFloorCeilingAndSixWallsWithInwardNormals) {
  RoomShape r{"L", kL, 0.0, 3.0, 0.2, 0.5, 0.7};
  const auto faces = room_faces(r);
  ASSERT_EQ(faces.size(), 8u);
  EXPECT_EQ(faces[0].label, "room \"L\" floor");
  EXPECT_EQ(faces[0].normal, Vec3(0, 0, 1));
  EXPECT_EQ(faces[1].normal, Vec3(0, 0, -1));
  EXPECT_DOUBLE_EQ(faces[1].reflectance, 0.7);
  // Wall 0 runs along y = 0 from x = 0 to 6: into the room is +y.
  EXPECT_EQ(faces[2].label, "room \"L\" wall 0");
  EXPECT_EQ(faces[2].normal, Vec3(0, 1, 0));
  // Wall 3 runs from (3,3) to (3,6), the inner corner's second wall: into the room is -x.
  EXPECT_EQ(faces[5].normal, Vec3(-1, 0, 0));
  // Every face's corners turn counter-clockwise about its normal.
  for (const auto& f : faces) {
    Vec3 n(0.0);
    for (size_t i = 0; i < f.corners.size(); ++i) {
      n += glm::cross(f.corners[i], f.corners[(i + 1) % f.corners.size()]);
    }
    EXPECT_GT(glm::dot(n, f.normal), 0.0) << f.label;
  }
  EXPECT_NEAR(face_area(faces[0]), 27.0, 1e-12);
  EXPECT_NEAR(face_area(faces[1]), 27.0, 1e-12);
  EXPECT_NEAR(face_area(faces[5]), 9.0, 1e-12);
}

TEST(Obstacles, BoxFacesPointOutward) {
  const Obstacle o = make_box("cabinet", {1, 1, 0}, {2, 1.5, 1.8}, 0.0, 0.4);
  const auto faces = obstacle_faces(o);
  ASSERT_EQ(faces.size(), 6u);
  EXPECT_EQ(faces[0].normal, Vec3(0, -1, 0));  // side along y = 1 faces -y
  EXPECT_EQ(faces[4].label, "obstacle \"cabinet\" top");
  EXPECT_EQ(faces[4].normal, Vec3(0, 0, 1));
  double area = 0.0;
  for (const auto& f : faces) area += face_area(f);
  EXPECT_NEAR(area, 2 * (1 * 0.5 + 1 * 1.8 + 0.5 * 1.8), 1e-12);
}

TEST(Obstacles, RotatedBoxTurnsAboutItsCentre) {
  const Obstacle o = make_box("b", {0, 0, 0}, {2, 2, 1}, kPi / 4, 0.0);
  // A 2 x 2 square turned by 45 degrees about (1, 1): corners on the axes through the centre.
  EXPECT_NEAR(o.footprint[0].x, 1.0, 1e-12);
  EXPECT_NEAR(o.footprint[0].y, 1.0 - std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(signed_area(o.footprint), 4.0, 1e-12);
}

TEST(Obstacles, BadBoxesAndPrisms) {
  try {
    make_box("cabinet", {0, 0, 1.8}, {1, 1, 0}, 0.0, 0.0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(
        e.what(),
        "obstacle \"cabinet\": box min must be below max in x, y and z, got z from 1.8 to 0");
  }
  try {
    make_prism("wall", {{0, 0}, {1, 0}, {1, 1}}, 2.0, 2.0, 0.0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "obstacle \"wall\": prism z0 must be below z1, got 2 and 2");
  }
  bool reversed = false;
  const Obstacle p = make_prism("col", {{0, 0}, {0, 1}, {1, 1}, {1, 0}}, 0, 3, 0.5, &reversed);
  EXPECT_TRUE(reversed);
  EXPECT_GT(signed_area(p.footprint), 0.0);
}

TEST(Polygon, TriangulationCoversNonConvexPolygons) {
  // An L, a U (two reflex corners) and a comb with collinear corners.
  const std::vector<Polygon2> polys = {
      kL,
      {{0, 0}, {5, 0}, {5, 4}, {4, 4}, {4, 1}, {1, 1}, {1, 4}, {0, 4}},
      {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}};
  for (const auto& p : polys) {
    double area = 0.0;
    for (const auto& t : triangulate(p)) {
      const double a = signed_area({p[t[0]], p[t[1]], p[t[2]]});
      EXPECT_GT(a, 0.0);
      area += a;
    }
    EXPECT_NEAR(area, signed_area(p), 1e-12);
  }
}

TEST(Polygon, ConvexityAndLocation) {
  EXPECT_FALSE(is_convex(kL));
  EXPECT_TRUE(is_convex({{0, 0}, {2, 0}, {4, 0}, {4, 4}, {0, 4}}));  // collinear corner allowed
  EXPECT_EQ(locate({1, 1}, kL), Location::inside);
  EXPECT_EQ(locate({4, 4}, kL), Location::outside);
  EXPECT_EQ(locate({3, 4}, kL), Location::boundary);
  EXPECT_EQ(locate({3, 3}, kL), Location::boundary);
}

}  // namespace
}  // namespace luxgrid::geometry
