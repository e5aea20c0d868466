// daylight.obstructions in the project file (project/project_daylight.cpp): boxes outside every
// room, read as docs/project-format.md gives them; a box touching a room's outside face (an
// overhang on the facade) loads; every refusal at its JSON pointer (reaching into a room, no
// volume, a reflectance outside [0, 1], an unknown key).
#include <gtest/gtest.h>

#include "project_error.h"

namespace luxgrid::project {
namespace {

nlohmann::json overhang_room() {
  return nlohmann::json::parse(R"({
    "format": "luxgrid-project/1",
    "rooms": [{"name": "r", "outline": [[0,0],[4,0],[4,4],[0,4]], "height": 3}],
    "openings": [{"name": "south", "room": "r", "polygon": [[1,0,1],[3,0,1],[3,0,2],[1,0,2]]}],
    "daylight": {"sky": {"type": "uniform"},
                 "obstructions": [
                   {"name": "overhang", "box": {"min": [-2,-1,3], "max": [6,0,3.2]},
                    "reflectance": 0.2},
                   {"box": {"min": [-10,-20,0], "max": [10,-15,9]}, "reflectance": 0}]},
    "surfaces": [{"name": "probes", "points": [{"at": [2, 2, 0], "normal": [0, 0, 1]}]}]
  })");
}

TEST(ExteriorObstructionsProject, LoadsBoxesTouchingTheFacade) {
  const Scene s = parse_project(overhang_room(), "p.json", ".").scene;
  ASSERT_EQ(s.daylight->obstructions.size(), 2u);
  const ExteriorObstruction& o = s.daylight->obstructions[0];
  EXPECT_EQ(o.name, "overhang");
  EXPECT_EQ(o.min, Vec3(-2, -1, 3));
  EXPECT_EQ(o.max, Vec3(6, 0, 3.2));
  EXPECT_EQ(o.reflectance, 0.2);
  EXPECT_EQ(s.daylight->obstructions[1].name, "obstruction 1");
}

TEST(ExteriorObstructionsProject, BoxReachingIntoARoomRefused) {
  auto d = overhang_room();
  d["daylight"]["obstructions"][0]["box"]["max"] = {6, 0.1, 3.2};  // 0.1 m into the wall's room
  d["daylight"]["obstructions"][0]["box"]["min"] = {-2, -1, 2.9};
  EXPECT_EQ(error_of(d),
            "p.json /daylight/obstructions/0/box: exterior obstruction \"overhang\" reaches into "
            "room \"r\" (an obstruction lies outside every room; inside one, give it as an "
            "obstacle of the room)");
}

TEST(ExteriorObstructionsProject, DegenerateBoxRefused) {
  auto d = overhang_room();
  d["daylight"]["obstructions"][1]["box"]["max"] = {10, -15, 0};  // no height
  EXPECT_EQ(error_of(d),
            "p.json /daylight/obstructions/1/box: exterior obstruction \"obstruction 1\": "
            "expected min < max in x, y and z (a box of positive volume)");
}

TEST(ExteriorObstructionsProject, ReflectanceOutsideRangeRefused) {
  auto d = overhang_room();
  d["daylight"]["obstructions"][0]["reflectance"] = 1.5;
  const std::string e = error_of(d);
  EXPECT_EQ(e.rfind("p.json /daylight/obstructions/0/reflectance: ", 0), 0u) << e;
  d["daylight"]["obstructions"][0].erase("reflectance");
  EXPECT_EQ(error_of(d).rfind("p.json /daylight/obstructions/0", 0), 0u) << error_of(d);
}

TEST(ExteriorObstructionsProject, UnknownKeyRefused) {
  auto d = overhang_room();
  d["daylight"]["obstructions"][0]["rotation_z"] = 10;
  EXPECT_NE(error_of(d).find("/daylight/obstructions/0"), std::string::npos) << error_of(d);
}

}  // namespace
}  // namespace luxgrid::project
