// Observers surfaces in the project loader: one point per view facing it, the N-direction
// shorthand, and every refusal naming its JSON pointer.
#include <gtest/gtest.h>

#include <cmath>

#include "project_error.h"
#include "util/error.h"

namespace luxgrid::project {
using namespace calc;
namespace {

nlohmann::json project() {
  return nlohmann::json::parse(R"({
    "format": "luxgrid-project/1",
    "photometry": { "lam": { "builtin": "lambertian", "intensity_cd": 500 } },
    "rooms": [ { "name": "r", "outline": [[0,0],[4,0],[4,3],[0,3]], "height": 2.8 } ],
    "luminaires": [ { "photometry": "lam", "position": [2, 1.5, 2.8],
                      "emitter": { "shape": "rectangle", "size": [0.6, 0.6] } } ],
    "surfaces": [ { "name": "eyes", "observers": [
      { "at": [1, 1, 1.2], "directions": 4 },
      { "at": [3, 2, 1.2], "directions": [[0, 2, 0], [1, 0, 0.5]] } ] } ]
  })");
}

TEST(ObserversProject, OnePointPerViewFacingIt) {
  const Scene s = parse_project(project(), "p.json", ".").scene;
  ASSERT_EQ(s.surfaces.size(), 1u);
  const auto& g = s.surfaces[0];
  EXPECT_EQ(g.kind, geometry::SurfaceGrid::Kind::observers);
  ASSERT_EQ(g.points.size(), 6u);
  EXPECT_EQ(g.observer, (std::vector<size_t>{0, 0, 0, 0, 1, 1}));
  // 4 directions: +x, +y, -x, -y, exactly (no 6e-17 from cos(pi / 2)).
  EXPECT_EQ(g.normals[0], Vec3(1, 0, 0));
  EXPECT_EQ(g.normals[1], Vec3(0, 1, 0));
  EXPECT_EQ(g.normals[2], Vec3(-1, 0, 0));
  EXPECT_EQ(g.normals[3], Vec3(0, -1, 0));
  EXPECT_EQ(g.normals[4], Vec3(0, 1, 0));  // normalised
  EXPECT_NEAR(g.normals[5].z, 0.5 / std::sqrt(1.25), 1e-15);
  EXPECT_EQ(g.points[5], Vec3(3, 2, 1.2));
}

TEST(ObserversProject, RefusalsNameThePlace) {
  auto d = project();
  d["surfaces"][0]["observers"][0]["directions"] = 0;
  EXPECT_EQ(error_of(d),
            "p.json /surfaces/0/observers/0/directions: expected a whole number of horizontal "
            "directions from 1 to 360, got 0");
  d = project();
  d["surfaces"][0]["observers"][0]["directions"] = 2.5;
  EXPECT_NE(error_of(d).find("/surfaces/0/observers/0/directions: expected a whole number"),
            std::string::npos);
  d = project();
  d["surfaces"][0]["observers"][1]["directions"][1] = {0, 0, 1};
  EXPECT_EQ(
      error_of(d),
      "p.json /surfaces/0/observers/1/directions/1: a view direction must not be vertical (the "
      "position index measures heights above the line of sight in the vertical plane through it)");
  d = project();
  d["surfaces"][0]["observers"][1]["directions"][0] = {0, 0, 0};
  EXPECT_EQ(error_of(d),
            "p.json /surfaces/0/observers/1/directions/0: expected a non-zero direction");
  d = project();
  d["surfaces"][0]["observers"] = nlohmann::json::array();
  EXPECT_EQ(error_of(d), "p.json /surfaces/0/observers: expected at least one observer");
  d = project();
  d["surfaces"][0]["spacing"] = 0.5;
  EXPECT_EQ(error_of(d), "p.json /surfaces/0/spacing: an observers surface has no \"spacing\"");
  d = project();
  d["settings"] = {{"indirect", "off"}};
  EXPECT_NE(error_of(d).find("p.json /surfaces/0: an observers surface needs reflected light"),
            std::string::npos);
  d = project();
  d["luminaires"][0].erase("emitter");
  EXPECT_NE(error_of(d).find(
                "p.json /surfaces/0: an observers surface needs every luminaire's luminous area"),
            std::string::npos);
  d = project();
  d["surfaces"][0]["points"] = nlohmann::json::array();
  EXPECT_EQ(error_of(d),
            "p.json /surfaces/0: expected exactly one of \"workplane\", \"plane\", \"points\" or "
            "\"observers\"");
}

TEST(ObserversProject, ViewLuminairePairsAreLimited) {
  auto d = project();
  // 20 x 20 luminaires (400) x 4 observers x 360 directions = 576 000 pairs: under 1e6; x 2 over.
  d["luminaires"][0] = {
      {"photometry", "lam"},
      {"emitter", {{"shape", "rectangle"}, {"size", {0.1, 0.1}}}},
      {"array", {{"origin", {0.1, 0.1, 2.8}}, {"count", {20, 20}}, {"spacing", {0.15, 0.1}}}}};
  nlohmann::json obs = nlohmann::json::array();
  for (int k = 0; k < 7; ++k) obs.push_back({{"at", {1, 1, 1.2}}, {"directions", 360}});
  d["surfaces"][0]["observers"] = obs;
  EXPECT_EQ(
      error_of(d),
      "p.json /surfaces/0/observers/6/directions: 400 luminaires x 2520 views = 1.008e+06 "
      "view-luminaire pairs, more than the limit of 1e+06 for observers surfaces; use fewer views "
      "or observers");
}

}  // namespace
}  // namespace luxgrid::project
