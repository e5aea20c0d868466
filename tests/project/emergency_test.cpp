// Emergency lighting [EN1838]: the escape-route and open-area points, their keys in the loader
// and every refusal, and the emergency scene (which luminaires, at which output, no reflections).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "calc/emergency_scene.h"
#include "calc/scaled_distribution.h"
#include "project_error.h"

namespace luxgrid::calc {
using project::error_of;
namespace {

// Distance from p to the segment ab.
double segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return glm::length(p - (a + t * ab));
}

double path_distance(Vec2 p, const geometry::Polygon2& path) {
  double d = 1e300;
  for (size_t k = 0; k + 1 < path.size(); ++k)
    d = std::min(d, segment_distance(p, path[k], path[k + 1]));
  return d;
}

TEST(EscapeRoute, StationsEveryStepCornersAndEndsIncluded) {
  // An L: 4 m along +x, then 2.5 m along +y; spacing 1 m gives 4 + 3 steps (2.5 m needs 3 of
  // 0.833 m), so 8 stations, the corner (4, 0) and both ends among them.
  const geometry::Polygon2 path{{0, 0}, {4, 0}, {4, 2.5}};
  const auto p = escape_route_points(path, 1.6, 1.0);
  ASSERT_EQ(p.centre_line.size(), 8u);
  EXPECT_EQ(p.centre_line.front(), Vec2(0, 0));
  EXPECT_EQ(p.centre_line[4], Vec2(4, 0));
  EXPECT_EQ(p.centre_line.back(), Vec2(4, 2.5));
  EXPECT_NEAR(glm::length(p.centre_line[5] - Vec2(4, 2.5 / 3)), 0.0, 1e-15);
  for (size_t k = 0; k + 1 < p.centre_line.size(); ++k) {
    EXPECT_LE(glm::length(p.centre_line[k + 1] - p.centre_line[k]),
              1.0 + 1e-12);  // never beyond the spacing
  }
  // The band is half of 1.6 m: 0.4 m each side of the centre; 0.4 / 1 m rounds up to one step,
  // so 3 points per station at -0.4, 0, +0.4 m across the station's segment.
  ASSERT_EQ(p.band.size(), 3 * p.centre_line.size());
  EXPECT_NEAR(glm::length(p.band[0] - Vec2(0, -0.4)), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(p.band[2] - Vec2(0, 0.4)), 0.0, 1e-15);
  // The corner belongs to the first segment (across = +y); the last station to the second (across =
  // -x).
  EXPECT_NEAR(glm::length(p.band[3 * 4] - Vec2(4, -0.4)), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(p.band[3 * 7] - Vec2(4.4, 2.5)), 0.0, 1e-15);
  // Every band point lies within the central band (0.4 m of the centre line), every centre-line
  // point on it, and the band's middle points are the centre line.
  for (const Vec2& b : p.band) EXPECT_LE(path_distance(b, path), 0.4 + 1e-12);
  for (size_t k = 0; k < p.centre_line.size(); ++k) {
    EXPECT_LT(path_distance(p.centre_line[k], path), 1e-12);
    EXPECT_EQ(p.band[3 * k + 1], p.centre_line[k]);
  }
  // The count the loader charges before building matches what is built.
  EXPECT_EQ(escape_route_point_count(path, 1.6, 1.0),
            static_cast<double>(p.centre_line.size() + p.band.size()));
  EXPECT_DOUBLE_EQ(path_length(path), 6.5);
}

TEST(EscapeRoute, FineSpacingCrossesTheBandInSteps) {
  // A 2 m route: band 1 m, 0.5 m each side; at spacing 0.2 m that is 3 steps a side (0.1667 m),
  // 7 points across, evenly from -0.5 to +0.5 m.
  const auto p = escape_route_points({{0, 0}, {1, 0}}, 2.0, 0.2);
  ASSERT_EQ(p.centre_line.size(), 6u);
  ASSERT_EQ(p.band.size(), 7u * 6u);
  for (int j = 0; j < 7; ++j) EXPECT_NEAR(p.band[j].y, -0.5 + j / 6.0, 1e-15);
  EXPECT_EQ(escape_route_point_count({{0, 0}, {1, 0}}, 2.0, 0.2), 48.0);
}

nlohmann::json project() {
  return nlohmann::json::parse(R"({
    "format": "luxgrid-project/1",
    "settings": { "scene": "emergency" },
    "photometry": { "iso": { "builtin": "isotropic", "intensity_cd": 100 },
                    "lam": { "builtin": "lambertian", "intensity_cd": 40 } },
    "rooms": [ { "name": "r", "outline": [[0,0],[6,0],[6,4],[0,4]], "height": 3, "floor_z": 0.5 } ],
    "luminaires": [ { "name": "a", "photometry": "iso", "position": [1, 1, 3], "emergency": { "fraction": 0.05 } },
                    { "name": "b", "photometry": "iso", "position": [3, 1, 3] },
                    { "name": "c", "photometry": "iso", "position": [5, 1, 3], "emergency": { "photometry": "lam" } },
                    { "name": "d", "photometry": "iso", "position": [5, 3, 3], "emergency": { "flux_lm": 100 } } ],
    "surfaces": [ { "name": "exit", "escape_route": { "path": [[0.5, 1], [5.5, 1]], "width": 1.2, "floor_z": 0.5 },
                    "spacing": 0.5 },
                  { "name": "hall", "open_area": { "room": "r" }, "spacing": 0.25 },
                  { "name": "eyes", "observers": [ { "at": [3, 3, 1.7], "directions": 2 } ] } ]
  })");
}

TEST(EmergencyProject, SurfacesAndRoles) {
  nlohmann::json d = project();
  d["surfaces"].erase(2);  // observers need luminous areas; not this test's subject
  const Scene s = project::parse_project(d, "p.json", ".").scene;
  EXPECT_EQ(s.settings.scene, LightingScene::emergency);
  ASSERT_EQ(s.surfaces.size(), 3u);
  EXPECT_EQ(s.surfaces[0].name, "exit centre line");
  EXPECT_EQ(s.surfaces[1].name, "exit band");
  EXPECT_EQ(s.surfaces[2].name, "hall");
  ASSERT_EQ(s.emergency_surfaces.size(), 3u);
  EXPECT_EQ(s.emergency_surfaces[0].role, EmergencyRole::route_centre_line);
  EXPECT_EQ(s.emergency_surfaces[1].role, EmergencyRole::route_band);
  EXPECT_EQ(s.emergency_surfaces[2].role, EmergencyRole::open_area);
  EXPECT_EQ(s.emergency_surfaces[2].entry, "hall");
  // Centre line: 5 m in 10 steps of 0.5 m, 11 stations on the floor (z = 0.5 m), facing up.
  const auto& centre = s.surfaces[0];
  ASSERT_EQ(centre.points.size(), 11u);
  for (size_t k = 0; k < centre.points.size(); ++k) {
    EXPECT_EQ(centre.points[k].z, 0.5);
    EXPECT_EQ(centre.normals[k], Vec3(0, 0, 1));
  }
  EXPECT_EQ(centre.quantity, geometry::Quantity::horizontal);
  // Open area: every active point at least 0.5 m inside the 6 m x 4 m outline, on the floor;
  // at 0.25 m the core 5 m x 3 m is 20 x 12 cells, all active.
  const auto& hall = s.surfaces[2];
  size_t active = 0;
  for (size_t k = 0; k < hall.points.size(); ++k) {
    if (!hall.active[k]) continue;
    ++active;
    const Vec3 p = hall.points[k];
    EXPECT_GE(std::min({p.x, 6.0 - p.x, p.y, 4.0 - p.y}), 0.5);
    EXPECT_EQ(p.z, 0.5);
  }
  EXPECT_EQ(active, 240u);
  EXPECT_EQ(hall.quantity, geometry::Quantity::horizontal);
}

TEST(EmergencyProject, RefusalsNameThePlace) {
  auto d = project();
  d["surfaces"][0]["escape_route"]["width"] = 2.5;
  EXPECT_EQ(
      error_of(d),
      "p.json /surfaces/0/escape_route/width: EN 1838's escape-route rules hold for routes up to "
      "2 m wide, got 2.5 m; give a wider route as several routes of at most 2 m, or as an "
      "open_area");
  d = project();
  d["surfaces"][0]["escape_route"]["path"] = {{0, 0}};
  EXPECT_EQ(error_of(d),
            "p.json /surfaces/0/escape_route/path: expected at least 2 corners (the route's centre "
            "line)");
  d = project();
  d["surfaces"][0]["escape_route"]["path"] = {{0, 0}, {0, 0}};
  EXPECT_EQ(error_of(d),
            "p.json /surfaces/0/escape_route/path/1: the corner repeats the one before it");
  d = project();
  d["surfaces"][0]["quantity"] = "vertical";
  EXPECT_EQ(
      error_of(d),
      "p.json /surfaces/0/quantity: an EN 1838 surface measures horizontal illuminance on the "
      "floor; it has no \"quantity\"");
  d = project();
  d["surfaces"][1]["open_area"]["outline"] = {{0, 0}, {0.9, 0}, {0.9, 0.9}, {0, 0.9}};
  EXPECT_EQ(
      error_of(d),
      "p.json /surfaces/1/open_area: the 0.5 m border that EN 1838 leaves out of an open area "
      "leaves no core area");
  d = project();
  d["surfaces"][1]["points"] = nlohmann::json::array();
  EXPECT_NE(error_of(d).find("p.json /surfaces/1: expected exactly one of"), std::string::npos);
  d = project();
  d["luminaires"][0]["emergency"] = {{"fraction", 0}};
  EXPECT_EQ(error_of(d),
            "p.json /luminaires/0/emergency/fraction: expected a fraction in (0, 1], got 0");
  d = project();
  d["luminaires"][0]["emergency"] = {{"fraction", 0.5}, {"flux_lm", 10}};
  EXPECT_EQ(error_of(d),
            "p.json /luminaires/0/emergency: expected exactly one of \"fraction\", \"flux_lm\" or "
            "\"photometry\"");
  d = project();
  d["luminaires"][0]["emergency"] = {{"photometry", "nope"}};
  EXPECT_EQ(error_of(d),
            "p.json /luminaires/0/emergency/photometry: no photometry entry named \"nope\"");
  d = project();
  d["luminaires"][3]["emergency"] = {
      {"flux_lm", 2000}};  // the isotropic 100 cd emits 400 pi = 1257 lm
  EXPECT_NE(
      error_of(d).find(
          "p.json /luminaires/3/emergency/flux_lm: the emergency flux 2000 lm is more than the "
          "luminaire's own 1256"),
      std::string::npos)
      << error_of(d);
  d = project();
  d["settings"]["scene"] = "night";
  EXPECT_EQ(error_of(d),
            "p.json /settings/scene: expected \"normal\", \"emergency\" or \"daylight\", got "
            "\"night\"");
  d = project();
  d["settings"]["maintenance"] = {{"luminaire_category", "C"}, {"environment", "clean"}};
  EXPECT_NE(error_of(d).find("the CIE 97 table form of the maintenance factor is not built"),
            std::string::npos)
      << error_of(d);
}

TEST(EmergencyScene, OnlyEmergencyLuminairesAtTheirEmergencyOutputWithoutReflections) {
  auto d = project();
  d["surfaces"][2]["observers"][0]["at"] = {3, 3, 1.7};
  // Observers need luminous areas in the normal scene; give every luminaire one.
  for (auto& l : d["luminaires"]) l["emitter"] = {{"shape", "disk"}, {"diameter", 0.1}};
  const Scene normal = project::parse_project(d, "p.json", ".").scene;
  const Scene e = make_emergency_scene(normal);
  EXPECT_EQ(e.settings.indirect, IndirectMode::off);
  ASSERT_EQ(e.luminaires.size(), 3u);
  EXPECT_EQ(e.luminaires[0].label, "a");
  EXPECT_EQ(e.luminaires[1].label, "c");
  EXPECT_EQ(e.luminaires[2].label, "d");
  const Vec3 down(0, 0, -1), side(1, 0, 0);
  // a: 5 % of 100 cd in every direction.
  EXPECT_DOUBLE_EQ(e.luminaires[0].distribution->intensity(down), 5.0);
  EXPECT_DOUBLE_EQ(e.luminaires[0].distribution->intensity(side), 5.0);
  // c: the Lambertian 40 cd entry in place of its own isotropic one.
  EXPECT_DOUBLE_EQ(e.luminaires[1].distribution->intensity(down), 40.0);
  EXPECT_EQ(e.luminaires[1].distribution->intensity(side), 0.0);
  EXPECT_EQ(e.luminaires[1].photometry, "lam");
  // d: scaled to 100 lm. An isotropic source of I cd emits 4 pi I lm, so I = 100 / (4 pi);
  // luminous_flux integrates numerically, so the factor carries its quadrature error; 1e-6
  // relative allows for it on a constant distribution while catching any wrong factor.
  EXPECT_NEAR(e.luminaires[2].distribution->intensity(down), 100.0 / (4.0 * kPi),
              1e-6 * 100.0 / (4.0 * kPi));
  // The observers surface is gone; the notes say what was done.
  ASSERT_EQ(e.surfaces.size(), 3u);
  for (const auto& g : e.surfaces) EXPECT_NE(g.kind, geometry::SurfaceGrid::Kind::observers);
  ASSERT_EQ(e.notes.size(), 2u);
  EXPECT_EQ(e.notes[0].kind, SceneNote::Kind::emergency_scene);
  EXPECT_EQ(e.notes[0].luminaires, 3u);
  EXPECT_EQ(e.notes[0].of_luminaires, 4u);
  // Each output as the project gave it: a fraction, a photometry entry, a flux.
  ASSERT_EQ(e.notes[0].outputs.size(), 3u);
  EXPECT_EQ(e.notes[0].outputs[0].luminaire, "a");
  EXPECT_EQ(e.notes[0].outputs[0].factor, 0.05);
  EXPECT_EQ(e.notes[0].outputs[1].photometry, "lam");
  EXPECT_EQ(e.notes[0].outputs[2].flux_lm, 100.0);
  EXPECT_EQ(e.notes[1].kind, SceneNote::Kind::observers_left_out);
  EXPECT_EQ(e.notes[1].observers, 1u);
  // The normal scene is untouched.
  EXPECT_EQ(normal.luminaires.size(), 4u);
  EXPECT_DOUBLE_EQ(normal.luminaires[0].distribution->intensity(down), 100.0);
}

TEST(EmergencyScene, RefusedWithoutEmergencyLuminaires) {
  auto d = project();
  d["surfaces"].erase(2);
  for (auto& l : d["luminaires"]) l.erase("emergency");
  const Scene normal = project::parse_project(d, "p.json", ".").scene;
  try {
    make_emergency_scene(normal);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no luminaire has an \"emergency\" entry"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace luxgrid::calc
