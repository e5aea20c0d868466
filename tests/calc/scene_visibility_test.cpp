// Visibility in scenes: a point source in one leg of an L-shaped room lights the other leg only
// where the inner corner does not hide it (exactly 0 lx behind it, the analytic I cos / d^2 where
// seen); a box between a source and a point gives 0; the plan's on/off reason.
#include <gtest/gtest.h>

#include "calc/direct.h"
#include "calc/pipeline.h"
#include "calc/scene_visibility.h"
#include "project/project_file.h"

#include <filesystem>

namespace luxgrid::calc {
namespace {

Scene scene_from(const std::string& rooms, const std::string& lamp) {
  return project::parse_project(nlohmann::json::parse(R"({
    "format": "luxgrid-project/1",
    "photometry": { "iso": { "builtin": "isotropic", "intensity_cd": 1000 } },
    "rooms": )" + rooms + R"(,
    "luminaires": [ { "photometry": "iso", "position": )" +
                                                      lamp + R"( } ],
    "surfaces": [ { "name": "p", "points": [ { "at": [1, 1, 0], "normal": [0, 0, 1] } ] } ]
  })"),
                                "v.json", ".")
      .scene;
}

const char* kLRoom =
    R"([ { "name": "L", "outline": [[0,0],[6,0],[6,3],[3,3],[3,6],[0,6]], "height": 3 } ])";

// E with visibility, as the direct calculation will form it.
double shadowed(const geometry::Visibility* vis, const Luminaire& lum, const Vec3& p) {
  if (geometry::blocked(vis, lum.pose.position, p)) return 0.0;
  return far_field_illuminance(lum, p, Vec3(0, 0, 1));
}

TEST(Visibility, LRoomPointSourceDarkBehindTheCorner) {
  const Scene scene = scene_from(kLRoom, "[1, 5, 2.9]");
  VisibilityDecision reason;
  const auto vis = make_visibility(scene, reason);
  ASSERT_TRUE(vis);
  EXPECT_TRUE(reason.on);
  EXPECT_EQ(reason.non_convex_rooms, std::vector<std::string>{"L"});
  const Luminaire& lum = scene.luminaires[0];
  const double h = 2.9;
  // Visible: E = I h / d^3 (isotropic source, horizontal receiver).
  for (const Vec3 p : {Vec3(1, 1, 0), Vec3(2.5, 1, 0), Vec3(5.5, 0.2, 0)}) {
    const double d = glm::length(p - lum.pose.position);
    EXPECT_NEAR(shadowed(vis.get(), lum, p), 1000.0 * h / (d * d * d), 1e-12) << p.x << "," << p.y;
  }
  // Hidden by the inner corner at (3, 3): the segments leave the room through wall 3.
  for (const Vec3 p : {Vec3(5.5, 1.0, 0), Vec3(5.5, 2.0, 0), Vec3(4.0, 2.5, 0)}) {
    EXPECT_GT(far_field_illuminance(lum, p, Vec3(0, 0, 1)), 0.0);  // unshadowed it would be lit
    EXPECT_EQ(shadowed(vis.get(), lum, p), 0.0) << p.x << "," << p.y;
  }
}

TEST(Visibility, BoxBetweenSourceAndPointGivesZero) {
  const Scene scene =
      scene_from(R"([ { "name": "r", "outline": [[0,0],[4,0],[4,4],[0,4]], "height": 3,
      "obstacles": [ { "name": "cabinet", "box": { "min": [1.5, 1.5, 0], "max": [2.5, 2.5, 1.8] } } ] } ])",
                 "[2, 2, 3]");
  VisibilityDecision reason;
  const auto vis = make_visibility(scene, reason);
  ASSERT_TRUE(vis);
  EXPECT_TRUE(reason.on);
  EXPECT_EQ(reason.obstacles, 1u);
  const Luminaire& lum = scene.luminaires[0];
  EXPECT_EQ(shadowed(vis.get(), lum, Vec3(2, 2, 0)), 0.0);      // under the cabinet
  EXPECT_EQ(shadowed(vis.get(), lum, Vec3(2.6, 2.0, 0)), 0.0);  // in its shadow beside it
  // On the cabinet's top the point is lit, at the analytic value: E = I / h^2 at 1.2 m.
  EXPECT_NEAR(shadowed(vis.get(), lum, Vec3(2, 2, 1.8)), 1000.0 / (1.2 * 1.2), 1e-9);
  // Far enough out the shadow ends: the ray to (3.9, 2, 0) is at z = 3 - 3 * 0.5 / 1.9 = 2.21
  // above the cabinet's edge at x = 2.5.
  EXPECT_GT(shadowed(vis.get(), lum, Vec3(3.9, 2.0, 0)), 0.0);
}

TEST(Visibility, OffForAConvexEmptyRoomWithTheLuminaireInside) {
  VisibilityDecision reason;
  const Scene scene =
      scene_from(R"([ { "name": "r", "outline": [[0,0],[4,0],[4,4],[0,4]], "height": 3 } ])",
                 "[2, 2, 3]");  // on the ceiling: inside the closed room
  EXPECT_EQ(make_visibility(scene, reason), nullptr);
  EXPECT_FALSE(reason.on);
  EXPECT_FALSE(reason.no_rooms);
  const Scene outside = scene_from(
      R"([ { "name": "r", "outline": [[0,0],[4,0],[4,4],[0,4]], "height": 3 } ])", "[2, 2, 3.5]");
  EXPECT_NE(make_visibility(outside, reason), nullptr);
  EXPECT_EQ(reason.luminaires_outside, 1u);
  EXPECT_EQ(reason.first_outside, "luminaire 0");
  const Scene no_rooms = scene_from("[]", "[2, 2, 3]");
  EXPECT_EQ(make_visibility(no_rooms, reason), nullptr);
  EXPECT_FALSE(reason.on);
  EXPECT_TRUE(reason.no_rooms);
}

TEST(Visibility, Cie171Case57ShadowEdgesMatchTheDerivation) {
  // cases/cie171_5_7_obstruction: S2 is the wall y = 4; from the floor point (2, 0.5, 0) the
  // README's z_min = (4 - 0.5) / (1.9 - 0.5) = 2.5 m; from the wall point (2, 0, 0.5)
  // z_min = 0.5 + 0.5 * 4 / 1.9 = 1.5526 m. The AABB tree must agree on both sides of each edge.
  const Scene scene = project::load_project(std::filesystem::path(LUXGRID_SOURCE_DIR) /
                                            "cases/cie171_5_7_obstruction/project.json")
                          .scene;
  VisibilityDecision reason;
  const auto vis = make_visibility(scene, reason);
  ASSERT_TRUE(vis);
  EXPECT_TRUE(reason.on);
  EXPECT_EQ(reason.obstacles, 1u);
  EXPECT_TRUE(scene.warnings.empty());
  // The emitter faces into the room: its nadir (local -z) is world -y.
  EXPECT_NEAR(glm::length(scene.luminaires[0].pose.rotation * Vec3(0, 0, -1) - Vec3(0, -1, 0)), 0.0,
              1e-12);
  for (double x : {0.1, 2.0, 3.9}) {
    EXPECT_FALSE(vis->visible(Vec3(2, 0.5, 0), Vec3(x, 4, 2.5 - 1e-6)));
    EXPECT_TRUE(vis->visible(Vec3(2, 0.5, 0), Vec3(x, 4, 2.5 + 1e-6)));
    EXPECT_FALSE(vis->visible(Vec3(2, 0, 0.5), Vec3(x, 4, 0.5 + 0.5 * 4 / 1.9 - 1e-6)));
    EXPECT_TRUE(vis->visible(Vec3(2, 0, 0.5), Vec3(x, 4, 0.5 + 0.5 * 4 / 1.9 + 1e-6)));
  }
  // In the umbra (y = 1.5) even the top corner of S2 is hidden; in front (y = 3) the bottom
  // corner region is seen (a segment lying in the floor plane itself would graze the floor and
  // count as blocked; it carries no light, cos = 0).
  EXPECT_FALSE(vis->visible(Vec3(2, 1.5, 0), Vec3(0, 4, 3)));
  EXPECT_TRUE(vis->visible(Vec3(2, 3, 0), Vec3(0.01, 4, 0.01)));
}

TEST(Visibility, EarlierCasesNeedNone) {
  // The point-source cases sit in empty convex black rooms with their sources on the ceiling:
  // visibility must stay off so their results cannot change.
  for (const char* c : {"cie171_5_2_directional_point", "point_isotropic_horizontal",
                        "point_isotropic_vertical", "point_lambertian_tilted"}) {
    const Scene scene = project::load_project(std::filesystem::path(LUXGRID_SOURCE_DIR) / "cases" /
                                              c / "project.json")
                            .scene;
    VisibilityDecision reason;
    EXPECT_EQ(make_visibility(scene, reason), nullptr) << c;
  }
}

TEST(Visibility, LShapeExampleLoads) {
  const Scene scene = project::load_project(std::filesystem::path(LUXGRID_SOURCE_DIR) /
                                            "examples/lshape/project.json")
                          .scene;
  EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front().text();
  VisibilityDecision reason;
  const auto vis = make_visibility(scene, reason);
  ASSERT_TRUE(vis);
  EXPECT_EQ(reason.obstacles, 2u);
  EXPECT_EQ(reason.non_convex_rooms, std::vector<std::string>{"L office"});
  EXPECT_EQ(vis->triangle_count(), 20u + 2u * 12u);
  ASSERT_EQ(scene.surfaces.size(), 1u + 8u);
  const auto& wp = scene.surfaces[0];
  EXPECT_EQ(wp.nu, 35);  // inset L spans 0.5..7.5: 7 m / 0.2 m
  // The missing 4 x 4 m quadrant's 20 x 20 cells but (3.6, 3.6), 0.566 m from the reflex corner
  // (4, 4), its nearest wall point: inside the border's arc there, not cut by a mitre.
  EXPECT_EQ(wp.points_outside, 399u);
  // Centres 0.5 + (i + 0.5) * 0.2 strictly inside a footprint, counted apart with the same
  // arithmetic: the column gives 2 (its faces lie on rows of centres, so rounding decides), the
  // cabinet (1.6 x 0.5 m about (2, 3.75), turned 20 degrees) 19.
  EXPECT_EQ(wp.points_in_obstacles, 21u);
}

// An opening larger than its convex room (a 6 x 6 m Lambertian panel under the ceiling of a
// 4 x 4 m room) reaches through the walls: the walls must hide its part outside. Its luminance is
// I0 / A, so the part inside (16 of its 36 m^2) gives exactly 16/36 of the light of a 4 x 4 m
// panel of the same I0 filling the ceiling. Tolerance 0.5 %: the reference near field resolves
// the visibility edge at the walls to its quadrature cells.
TEST(Visibility, OpeningReachingThroughTheWallsIsClippedByThem) {
  auto scene_with = [](double size_m) {
    return project::parse_project(nlohmann::json::parse(R"({
      "format": "luxgrid-project/1", "settings": { "quality": "reference", "indirect": "off" },
      "photometry": { "panel": { "builtin": "lambertian", "intensity_cd": 1000 } },
      "rooms": [ { "name": "r", "outline": [[0,0],[4,0],[4,4],[0,4]], "height": 3 } ],
      "luminaires": [ { "photometry": "panel", "position": [2, 2, 2.999],
                        "emitter": { "shape": "rectangle", "size": [)" +
                                                        std::to_string(size_m) + ", " +
                                                        std::to_string(size_m) + R"(] } } ],
      "surfaces": [ { "name": "p", "points": [ { "at": [2, 2, 0], "normal": [0, 0, 1] },
                                              { "at": [0.5, 1, 0.8], "normal": [0, 0, 1] } ] } ]
    })"),
                                  "v.json", ".")
        .scene;
  };
  const Scene big = scene_with(6.0), filling = scene_with(4.0);
  VisibilityDecision reason;
  EXPECT_TRUE(make_visibility(big, reason));
  EXPECT_EQ(reason.openings_reaching, 1u);
  EXPECT_EQ(reason.first_reaching, "luminaire 0");
  EXPECT_FALSE(make_visibility(filling, reason));
  const Results rb = run_scene(big), rf = run_scene(filling);
  for (size_t i = 0; i < 2; ++i) {
    const double expected = 16.0 / 36.0 * rf.surfaces[0].E_direct[i];
    EXPECT_NEAR(rb.surfaces[0].E_direct[i] / expected, 1.0, 5e-3) << "point " << i;
  }
}

}  // namespace
}  // namespace luxgrid::calc
