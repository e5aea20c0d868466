// Soft shadows of area luminaires through the whole direct calculation (docs/geometry.md, and its
// "done when": an area source half-hidden by an edge gives the exact Lambert value of its visible
// part). A 1 x 1 Lambertian panel in the ceiling (z = 3) of a 4 x 4 x 3 m room, over a full-width
// partition x in [1.9, 2.0], z in [0, 1.5]. From a floor point R = (x_r, y, 0) with x_r < 1.9 a ray
// to the panel point (x_p, y_p, 3) passes over the partition iff it is above z = 1.5 at both of its
// top edges; the near edge x = 1.9 binds: z = 3 (1.9 - x_r) / (x_p - x_r) >= 1.5, i.e.
// x_p <= 3.8 - x_r. So R sees the strip x_p in [1.5, min(2.5, 3.8 - x_r)] of the panel, whatever y.
#include <gtest/gtest.h>

#include <algorithm>

#include "calc/direct.h"
#include "calc/nearfield/models.h"
#include "calc/plan.h"
#include "photometry/builtin.h"
#include "project/project_file.h"

namespace luxgrid::calc {
namespace {

constexpr double kI0 = 1000.0;  // cd, so L = 1000 cd/m^2 on the 1 m^2 panel

Scene partition_scene(const std::string& obstacles) {
  return project::parse_project(nlohmann::json::parse(R"({
    "format": "luxgrid-project/1",
    "settings": { "quality": "standard", "indirect": "off", "near_field": "always" },
    "photometry": { "panel": { "builtin": "lambertian", "intensity_cd": 1000 } },
    "rooms": [ { "name": "r", "outline": [[0,0],[4,0],[4,4],[0,4]], "height": 3,
                 "reflectance": { "floor": 0, "walls": 0, "ceiling": 0 },
                 "obstacles": )" + obstacles + R"( } ],
    "luminaires": [ { "photometry": "panel", "position": [2, 2, 3],
                      "emitter": { "shape": "rectangle", "size": [1, 1] } } ],
    "surfaces": [ { "name": "floor", "points": [
      { "at": [1.0, 2.0, 0], "normal": [0, 0, 1] },
      { "at": [1.5, 2.0, 0], "normal": [0, 0, 1] },
      { "at": [1.5, 1.7, 0], "normal": [0, 0, 1] },
      { "at": [1.65, 2.3, 0], "normal": [0, 0, 1] },
      { "at": [1.8, 2.0, 0], "normal": [0, 0, 1] },
      { "at": [1.85, 1.6, 0], "normal": [0, 0, 1] } ] } ]
  })"),
                                "soft.json", ".")
      .scene;
}

const char* kPartition =
    R"([ { "name": "partition", "box": { "min": [1.9, 0, 0], "max": [2.0, 4, 1.5] } } ])";

// Exact value of the visible strip by Lambert's formula (nearfield::lambert_uniform_illuminance).
double exact_visible(const Vec3& r) {
  const double xc = std::min(2.5, 3.8 - r.x);
  if (xc <= 1.5) return 0.0;
  const nearfield::Emitter strip = nearfield::make_polygon_emitter(
      {{xc, 2.5, 3.0}, {1.5, 2.5, 3.0}, {1.5, 1.5, 3.0}, {xc, 1.5, 3.0}}, glm::dmat3(1.0),
      std::make_shared<photometry::LambertianDistribution>(kI0));
  return nearfield::lambert_uniform_illuminance(strip, r, Vec3(0, 0, 1), kI0);
}

TEST(SoftShadow, PanelHalfHiddenByAPartitionGivesLambertOfItsVisiblePart) {
  const Scene scene = partition_scene(kPartition);
  const Plan plan = make_plan(scene);
  ASSERT_TRUE(plan.visibility_test);
  EXPECT_TRUE(plan.visibility.on);
  const auto emitters = make_emitters(scene);
  const auto& grid = scene.surfaces.at(0);
  const std::vector<double> E = direct_illuminance(plan, emitters, grid);
  ASSERT_EQ(E.size(), 6u);
  for (size_t i = 0; i < E.size(); ++i) {
    const Vec3 p = grid.points[i];
    const double exact = exact_visible(p);
    // `standard` is held to 1 % of the reference (docs/accuracy.md); the shadow edge is refined
    // until its cells carry less than that (calc/nearfield/ladder.cpp).
    EXPECT_NEAR(E[i], exact, 0.01 * exact) << p.x << ", " << p.y;
  }
  // The first point sees the whole panel, the last ones less than half of it.
  const double full =
      nearfield::lambert_uniform_illuminance(emitters[0], grid.points[0], Vec3(0, 0, 1), kI0);
  EXPECT_NEAR(E[0], full, 0.01 * full);
  EXPECT_LT(E[4], 0.6 * nearfield::lambert_uniform_illuminance(emitters[0], grid.points[4],
                                                               Vec3(0, 0, 1), kI0));
}

TEST(SoftShadow, PanelFullyHiddenGivesZero) {
  // A partition up to z = 2.9 right under the panel's near edge hides all of it from x_r <= 1.
  const Scene scene = partition_scene(
      R"([ { "name": "wall", "box": { "min": [1.3, 0, 0], "max": [1.4, 4, 2.9] } } ])");
  const Plan plan = make_plan(scene);
  ASSERT_TRUE(plan.visibility_test);
  const std::vector<double> E =
      direct_illuminance(plan, make_emitters(scene), scene.surfaces.at(0));
  EXPECT_EQ(E[0], 0.0);  // (1.0, 2.0): every ray to x_p >= 1.5 crosses x = 1.3 below z = 0.9
}

}  // namespace
}  // namespace luxgrid::calc
