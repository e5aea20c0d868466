// daylight.en17037 in the project file (project/project_daylight.cpp): the site's median, the
// level and the reference planes as docs/project-format.md gives them; the top-lit rule decided
// from the room's openings; every refusal at its JSON pointer (a missing median, an unknown
// level, a reference plane that is no workplane) and the warning for a plane off EN 17037's
// height.
#include <gtest/gtest.h>

#include "project_error.h"

namespace luxgrid::project {
namespace {

// A 4 x 4 x 3 m room with a south window, a workplane at EN 17037's 0.85 m and 0.5 m border.
nlohmann::json en17037_room() {
  return nlohmann::json::parse(R"({
    "format": "luxgrid-project/1",
    "rooms": [{"name": "r", "outline": [[0,0],[4,0],[4,4],[0,4]], "height": 3}],
    "openings": [{"name": "south", "room": "r", "polygon": [[1,0,1],[3,0,1],[3,0,2],[1,0,2]]}],
    "daylight": {"sky": {"type": "cie-overcast"},
                 "en17037": {"median_external_diffuse_lx": 14000, "level": "medium"}},
    "surfaces": [
      {"name": "wp", "workplane": {"room": "r", "height": 0.85, "border": 0.5}, "spacing": 0.5},
      {"name": "probe", "points": [{"at": [2, 2, 0], "normal": [0, 0, 1]}]}
    ]
  })");
}

Project load_en17037(const nlohmann::json& doc) { return parse_project(doc, "p.json", "."); }

TEST(En17037Project, LoadsTheRequest) {
  const Project p = load_en17037(en17037_room());
  ASSERT_TRUE(p.scene.daylight->en17037.has_value());
  const daylight::En17037Request& r = *p.scene.daylight->en17037;
  EXPECT_EQ(r.median_external_diffuse_lx, 14000.0);
  EXPECT_EQ(r.level, daylight::En17037Level::medium);
  // Every workplane when none is named; a window in a wall: side-lit.
  ASSERT_EQ(r.planes.size(), 1u);
  EXPECT_EQ(r.planes[0].surface, "wp");
  EXPECT_FALSE(r.planes[0].top_lit);
  EXPECT_TRUE(p.scene.warnings.empty());
}

TEST(En17037Project, TopLitWhenAllOpeningsAreInTheCeiling) {
  auto d = en17037_room();
  d["openings"][0]["polygon"] =
      nlohmann::json::parse("[[1.5,1.5,3],[2.5,1.5,3],[2.5,2.5,3],[1.5,2.5,3]]");
  EXPECT_TRUE(load_en17037(d).scene.daylight->en17037->planes[0].top_lit);
  // A roof light and a window: side-lit (the 50 % rule).
  d["openings"].push_back(
      {{"room", "r"}, {"polygon", nlohmann::json::parse("[[1,0,1],[3,0,1],[3,0,2],[1,0,2]]")}});
  EXPECT_FALSE(load_en17037(d).scene.daylight->en17037->planes[0].top_lit);
}

TEST(En17037Project, MissingMedianRefused) {
  auto d = en17037_room();
  d["daylight"]["en17037"].erase("median_external_diffuse_lx");
  EXPECT_EQ(error_of(d).rfind(
                "p.json /daylight/en17037: missing required key \"median_external_diffuse_lx\"", 0),
            0u)
      << error_of(d);
  d["daylight"]["en17037"]["median_external_diffuse_lx"] = 0;
  EXPECT_EQ(error_of(d).rfind("p.json /daylight/en17037/median_external_diffuse_lx: ", 0), 0u);
}

TEST(En17037Project, UnknownLevelRefused) {
  auto d = en17037_room();
  d["daylight"]["en17037"]["level"] = "maximum";
  EXPECT_EQ(error_of(d),
            "p.json /daylight/en17037/level: expected an EN 17037 level \"minimum\", \"medium\" "
            "or \"high\", got \"maximum\"");
  d["daylight"]["en17037"]["level"] = 2;
  EXPECT_EQ(error_of(d),
            "p.json /daylight/en17037/level: expected an EN 17037 level \"minimum\", \"medium\" "
            "or \"high\", got 2");
}

TEST(En17037Project, ReferencePlaneMustBeAWorkplane) {
  auto d = en17037_room();
  d["daylight"]["en17037"]["reference_planes"] = {"wp", "probe"};
  EXPECT_EQ(error_of(d),
            "p.json /daylight/en17037/reference_planes/1: no workplane surface is named \"probe\" "
            "(EN 17037's reference plane is a workplane: 0.85 m above the floor, border 0.5 m)");
  d["daylight"]["en17037"]["reference_planes"] = {"wp"};
  EXPECT_EQ(error_of(d), "(no error)");
  d["surfaces"].erase(0);
  d["daylight"]["en17037"].erase("reference_planes");
  EXPECT_EQ(error_of(d),
            "p.json /daylight/en17037: EN 17037 is assessed on a reference plane: give a "
            "workplane surface (0.85 m above the floor, border 0.5 m)");
}

TEST(En17037Project, PlaneOffTheStandardsHeightWarned) {
  auto d = en17037_room();
  d["surfaces"][0]["workplane"]["height"] = 0.8;
  const Project p = load_en17037(d);
  ASSERT_EQ(p.scene.warnings.size(), 1u);
  EXPECT_EQ(p.scene.warnings[0].text(),
            "p.json /surfaces/0/workplane: EN 17037's reference plane lies 0.85 m above the floor "
            "with a 0.5 m border; workplane \"wp\" has 0.8 m and 0.5 m: its EN 17037 fractions "
            "are not the standard's");
}

TEST(En17037Project, UnknownKeyRefused) {
  auto d = en17037_room();
  d["daylight"]["en17037"]["levle"] = "high";
  EXPECT_NE(error_of(d).find("/daylight/en17037/levle"), std::string::npos);
}

}  // namespace
}  // namespace luxgrid::project
