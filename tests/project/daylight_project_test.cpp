// Openings and daylight in the project file (project/project_daylight.cpp,
// calc/opening_placement): the keys as docs/project-format.md gives them, each face found, and
// every refusal at its JSON pointer (an opening off its face, crossing its edge, overlapping
// another; an unknown sky type; a transmittance outside (0, 1]).
#include <gtest/gtest.h>

#include "project_error.h"

namespace luxgrid::project {
namespace {

// CIE 171's daylight room: 4 x 4 x 3 m, no luminaires, no photometry.
nlohmann::json daylight_room() {
  return nlohmann::json::parse(R"({
    "format": "luxgrid-project/1",
    "rooms": [{"name": "r", "outline": [[0,0],[4,0],[4,4],[0,4]], "height": 3}],
    "openings": [
      {"name": "roof", "room": "r", "polygon": [[1.5,1.5,3],[2.5,1.5,3],[2.5,2.5,3],[1.5,2.5,3]]},
      {"name": "south", "room": "r", "polygon": [[1,0,1],[3,0,1],[3,0,2],[1,0,2]],
       "glazing": {"transmittance": 0.88}, "frame_factor": 0.8, "maintenance_factor": 0.9}
    ],
    "daylight": {"sky": {"type": 12}, "sun": {"altitude_deg": 60, "azimuth_deg": 180},
                 "diffuse_horizontal_lx": 10000, "ground": {"reflectance": 0.3}},
    "surfaces": [{"name": "probes", "points": [{"at": [2, 2, 0], "normal": [0, 0, 1]}]}]
  })");
}

Scene load(const nlohmann::json& doc) { return parse_project(doc, "p.json", ".").scene; }

TEST(DaylightProject, LoadsOpeningsAndSky) {
  const Scene s = load(daylight_room());
  ASSERT_EQ(s.openings.size(), 2u);
  EXPECT_EQ(s.openings[0].face.kind, RoomFaceRef::Kind::ceiling);
  EXPECT_EQ(s.openings[0].inward_normal, Vec3(0, 0, -1));
  EXPECT_FALSE(s.openings[0].glazing_transmittance.has_value());
  EXPECT_EQ(s.openings[1].face.kind, RoomFaceRef::Kind::wall);
  EXPECT_EQ(s.openings[1].face.wall, 0u);  // the edge from (0, 0) to (4, 0): y = 0, south
  EXPECT_NEAR(glm::length(s.openings[1].inward_normal - Vec3(0, 1, 0)), 0.0, 1e-15);
  EXPECT_EQ(*s.openings[1].glazing_transmittance, 0.88);
  EXPECT_EQ(s.openings[1].frame_factor, 0.8);
  EXPECT_EQ(s.openings[1].maintenance_factor, 0.9);
  ASSERT_TRUE(s.daylight.has_value());
  EXPECT_EQ(s.daylight->sky.kind, daylight::SkyKind::cie_general);
  EXPECT_EQ(s.daylight->sky.cie_type, 12);
  // The sun due south at 60 degrees: (0, -1/2, sqrt(3)/2).
  EXPECT_NEAR(s.daylight->sky.sun.y, -0.5, 1e-15);
  EXPECT_EQ(s.daylight->ground_reflectance, 0.3);
  EXPECT_TRUE(s.luminaires.empty());
}

// A whole wall is an opening (CIE 171's 4 x 3 m facade), and the floor holds one too.
TEST(DaylightProject, OpeningMayFillItsFace) {
  auto d = daylight_room();
  d["openings"] = nlohmann::json::parse(
      R"([{"room": "r", "polygon": [[0,0,0],[4,0,0],[4,0,3],[0,0,3]]},
          {"room": "r", "polygon": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]}])");
  const Scene s = load(d);
  EXPECT_EQ(s.openings[0].face.kind, RoomFaceRef::Kind::wall);
  EXPECT_EQ(s.openings[1].face.kind, RoomFaceRef::Kind::floor);
}

TEST(DaylightProject, OpeningOffItsFaceRefused) {
  auto d = daylight_room();
  d["openings"][1]["polygon"] = nlohmann::json::parse("[[1,0.1,1],[3,0,1],[3,0,2],[1,0,2]]");
  EXPECT_EQ(error_of(d),
            "p.json /openings/1/polygon: opening \"south\" lies in the plane of no face of room "
            "\"r\" (every corner must lie in the plane of one floor, ceiling or wall, within "
            "0.001 mm)");
}

TEST(DaylightProject, OpeningCrossingItsEdgeRefused) {
  auto d = daylight_room();
  d["openings"][1]["polygon"] = nlohmann::json::parse("[[3,0,1],[5,0,1],[5,0,2],[3,0,2]]");
  EXPECT_EQ(error_of(d),
            "p.json /openings/1/polygon: opening \"south\" crosses the edge of wall 0 of room "
            "\"r\" (an opening must lie within its face)");
  d["openings"][1]["polygon"] = nlohmann::json::parse("[[1,0,2],[3,0,2],[3,0,3.5],[1,0,3.5]]");
  EXPECT_NE(error_of(d).find("crosses the edge of wall 0"), std::string::npos);
}

TEST(DaylightProject, OverlappingOpeningsRefused) {
  auto d = daylight_room();
  d["openings"][0] = {{"name", "left"},
                      {"room", "r"},
                      {"polygon", nlohmann::json::parse("[[0.5,0,1],[2,0,1],[2,0,2],[0.5,0,2]]")}};
  EXPECT_EQ(error_of(d),
            "p.json /openings/1/polygon: opening \"south\" overlaps opening \"left\" in the same "
            "face");
  // Side by side in one band of height: no edge crosses another properly and no corner or
  // triangle centroid of one lies inside the other, yet they share 0.2 x 1 m.
  d["openings"][0]["polygon"] = nlohmann::json::parse("[[0.5,0,1],[1.2,0,1],[1.2,0,2],[0.5,0,2]]");
  EXPECT_EQ(error_of(d),
            "p.json /openings/1/polygon: opening \"south\" overlaps opening \"left\" in the same "
            "face");
  // Touching along an edge is no overlap.
  d["openings"][0]["polygon"] = nlohmann::json::parse("[[0.5,0,1],[1,0,1],[1,0,2],[0.5,0,2]]");
  EXPECT_EQ(error_of(d), "(no error)");
}

TEST(DaylightProject, UnknownSkyTypeRefused) {
  auto d = daylight_room();
  d["daylight"]["sky"]["type"] = 16;
  EXPECT_EQ(error_of(d),
            "p.json /daylight/sky/type: expected a CIE general sky type 1 to 15, \"cie-overcast\" "
            "or \"uniform\", got 16");
  d["daylight"]["sky"]["type"] = "overcast";
  EXPECT_EQ(error_of(d),
            "p.json /daylight/sky/type: expected a CIE general sky type 1 to 15, \"cie-overcast\" "
            "or \"uniform\", got \"overcast\"");
  d["daylight"]["sky"]["type"] = 2.5;
  EXPECT_NE(error_of(d).find("got 2.5"), std::string::npos);
}

TEST(DaylightProject, TransmittanceOutsideRangeRefused) {
  auto d = daylight_room();
  d["openings"][1]["glazing"]["transmittance"] = 0;
  EXPECT_EQ(error_of(d),
            "p.json /openings/1/glazing/transmittance: expected a normal transmittance in (0, 1], "
            "got 0");
  d["openings"][1]["glazing"]["transmittance"] = 1.2;
  EXPECT_NE(error_of(d).find("in (0, 1], got 1.2"), std::string::npos);
  d["openings"][1]["glazing"]["transmittance"] = 0.95;
  EXPECT_NE(error_of(d).find("/openings/1/glazing/transmittance: a clear pane of refractive index "
                             "1.52 transmits at most 0.918"),
            std::string::npos);
}

TEST(DaylightProject, GeneralSkyNeedsTheSun) {
  auto d = daylight_room();
  d["daylight"].erase("sun");
  EXPECT_NE(error_of(d).find("/daylight/sky/type: a CIE general sky is shaped by the sun"),
            std::string::npos);
  d["daylight"]["sky"]["type"] = "cie-overcast";
  EXPECT_EQ(error_of(d), "(no error)");
}

// The sun from a site and a local time (SPA): Golden, Colorado, 17 October 2003 12:30 local
// standard time has the sun near 39.9 degrees up, 194.3 degrees (calc/daylight tests it to the
// paper's digits); north angle 90 turns the plan so that the sun's azimuth 194 lies toward -x.
TEST(DaylightProject, SunFromSiteAndTime) {
  auto d = daylight_room();
  d["daylight"]["site"] = {{"latitude_deg", 39.742476},
                           {"longitude_deg", -105.1786},
                           {"timezone_h", -7},
                           {"north_angle_deg", 90}};
  d["daylight"]["sun"] = {{"local_time", "2003-10-17T12:30:30"}};
  const Scene s = load(d);
  ASSERT_TRUE(s.daylight->sun.has_value());
  EXPECT_NEAR(s.daylight->sun->altitude_deg, 39.89, 0.02);
  EXPECT_NEAR(s.daylight->sun->azimuth_deg, 194.34, 0.02);
  EXPECT_LT(s.daylight->sky.sun.x, -0.7);
  d["daylight"]["site"].erase("timezone_h");
  EXPECT_NE(error_of(d).find("/daylight/sun/local_time: the sun's position at a local time needs"),
            std::string::npos);
  d["daylight"]["site"]["timezone_h"] = -7;
  d["daylight"]["sun"]["local_time"] = "2003-13-17T12:30";
  EXPECT_NE(error_of(d).find("expected a local standard time"), std::string::npos);
}

TEST(DaylightProject, DaylightSceneNeedsDaylight) {
  auto d = daylight_room();
  d["settings"] = {{"scene", "daylight"}};
  const Scene s = load(d);
  EXPECT_EQ(s.settings.scene, LightingScene::daylight);
  d.erase("daylight");
  d["photometry"] = nlohmann::json::object();
  d["luminaires"] = nlohmann::json::array();
  EXPECT_EQ(error_of(d),
            "p.json /settings/scene: the daylight scene needs a \"daylight\" object (sky, sun, "
            "diffuse illuminance)");
}

TEST(DaylightProject, UnknownKeysRefused) {
  auto d = daylight_room();
  d["openings"][0]["glazing"] = {{"transmitance", 0.8}};
  EXPECT_NE(error_of(d).find("/openings/0/glazing"), std::string::npos);
  d = daylight_room();
  d["daylight"]["sky"]["turbidity"] = 3;
  EXPECT_NE(error_of(d).find("/daylight/sky/turbidity"), std::string::npos);
}

// Direct sun (daylight.sun.direct_normal_lx): read when given, absent by default; a value that is
// not a positive number, or the sun at or below the horizon, refused at its JSON pointer.
TEST(DaylightProject, DirectSunReadAndBadValuesRefused) {
  auto d = daylight_room();
  EXPECT_FALSE(load(d).daylight->direct_normal_lx.has_value());
  d["daylight"]["sun"]["direct_normal_lx"] = 80000;
  EXPECT_EQ(*load(d).daylight->direct_normal_lx, 80000.0);
  for (const double bad : {-1.0, 0.0}) {
    d["daylight"]["sun"]["direct_normal_lx"] = bad;
    EXPECT_NE(error_of(d).find("p.json /daylight/sun/direct_normal_lx: expected the sun's direct "
                               "normal illuminance in lx, a number > 0"),
              std::string::npos)
        << error_of(d);
  }
  d["daylight"]["sun"]["direct_normal_lx"] = "bright";
  EXPECT_NE(error_of(d).find("/daylight/sun/direct_normal_lx"), std::string::npos);
  // Below the horizon (an overcast sky does not need the sun above it; direct sun does).
  d["daylight"]["sky"]["type"] = "cie-overcast";
  d["daylight"]["sun"] = {{"altitude_deg", -5}, {"azimuth_deg", 180}, {"direct_normal_lx", 1000}};
  EXPECT_NE(error_of(d).find("/daylight/sun/direct_normal_lx: direct sun asked for, but the sun "
                             "is -5 degrees above the horizon"),
            std::string::npos)
      << error_of(d);
  d["daylight"]["sun"].erase("direct_normal_lx");
  EXPECT_EQ(error_of(d), "(no error)");
}

}  // namespace
}  // namespace luxgrid::project
