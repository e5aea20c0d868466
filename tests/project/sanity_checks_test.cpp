// Everyday mistakes become warnings that name the object by its JSON pointer and say what
// luxgrid assumed; the project still loads as written. Each test makes one mistake in a project
// that is otherwise clean (no warnings at all), so a warning that fires too eagerly fails too.
#include <gtest/gtest.h>

#include <algorithm>

#include "photometry/builtin.h"
#include "project/project_file.h"
#include "project/project_limits.h"
#include "project/sanity_checks.h"
#include "util/error.h"

namespace luxgrid::project {
using namespace calc;
namespace {

// A 6 x 4 x 2.8 m office, one Lambertian downlight in the middle, a workplane and a wall plane
// facing into the room.
nlohmann::json lit_office() {
  return nlohmann::json::parse(R"({
    "format": "luxgrid-project/1", "name": "t",
    "photometry": { "down": { "builtin": "lambertian", "intensity_cd": 1000 } },
    "rooms": [ { "name": "office", "outline": [[0,0],[6,0],[6,4],[0,4]], "height": 2.8 } ],
    "luminaires": [ { "name": "panel", "photometry": "down", "position": [3, 2, 2.8] } ],
    "surfaces": [
      { "name": "wp", "workplane": { "room": "office", "height": 0.8, "border": 0.5 }, "spacing": 0.5 },
      { "name": "south wall", "plane": { "origin": [6, 0, 0], "u": [-1, 0, 0], "v": [0, 0, 1], "size": [6, 2.8] },
        "spacing": 0.5 }
    ]
  })");
}

// The warnings as printed (util/error.h: place, then message).
std::vector<std::string> warnings_of(const nlohmann::json& doc, const std::string& base = ".") {
  std::vector<std::string> out;
  for (const auto& w : parse_project(doc, "p.json", base).scene.warnings) out.push_back(w.text());
  return out;
}

// The one warning of `doc`, which must contain every piece of `expected`.
void expect_one_warning(const nlohmann::json& doc, std::initializer_list<const char*> expected,
                        const std::string& base = ".") {
  const auto w = warnings_of(doc, base);
  ASSERT_EQ(w.size(), 1u) << (w.empty() ? "(none)"
                                        : w.front() + (w.size() > 1 ? " | " + w[1] : ""));
  for (const char* piece : expected)
    EXPECT_NE(w[0].find(piece), std::string::npos) << piece << "\n in: " << w[0];
}

TEST(SanityChecks, TheCleanOfficeHasNone) {
  EXPECT_EQ(warnings_of(lit_office()), std::vector<std::string>{});
}

TEST(SanityChecks, ARoomInMillimetresInPlanWarns) {
  // 1500 x 4 m in plan, 2.8 m high: the plan is in millimetres, the height (wrongly) not.
  auto doc = lit_office();
  doc["rooms"][0]["outline"] = nlohmann::json::parse("[[0,0],[1500,0],[1500,4],[0,4]]");
  expect_one_warning(doc, {"p.json /rooms/0: room \"office\": the room is", "1500 m x 4 m",
                           "looks like millimetres", "luxgrid reads every length in metres"});
}

TEST(SanityChecks, APlaneInMillimetresWarns) {
  auto doc = lit_office();
  doc["surfaces"][1] = nlohmann::json::parse(
      R"({ "name": "sign", "plane": { "origin": [0, 0, 0], "u": [1, 0, 0], "v": [0, 1, 0], "size": [2000, 1000] },
           "spacing": 200 })");
  expect_one_warning(doc, {"p.json /surfaces/1: surface \"sign\": the plane is", "2000 m x 1000 m",
                           "looks like millimetres"});
}

TEST(SanityChecks, ARoomHigherThanAnyHallIsRefusedAsMillimetres) {
  auto doc = lit_office();
  doc["rooms"][0]["height"] = 2800;
  try {
    (void)parse_project(doc, "p.json", ".");
    FAIL() << "accepted a 2800 m high room";
  } catch (const InputError& e) {
    EXPECT_EQ(
        std::string(e.what()),
        "p.json /rooms/0/height: the room \"office\" is 2800 m high, more than the limit of 1000 m "
        "for a "
        "room; the lengths look like millimetres, and luxgrid reads metres (divide them by 1000)");
  }
  doc["rooms"][0]["height"] = kMaxRoomHeight_m;  // the limit itself is a room
  doc["luminaires"][0]["position"] = {3, 2, kMaxRoomHeight_m};
  EXPECT_NO_THROW(parse_project(doc, "p.json", ".").scene);
}

TEST(SanityChecks, ASpacingLargerThanTheSurfaceWarnsAndSoDoesTheOnePointGrid) {
  // "spacing": 250 meant in millimetres: the 5 x 3 m workplane becomes one cell.
  auto doc = lit_office();
  doc["surfaces"][0]["spacing"] = 250;
  const auto w = warnings_of(doc);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(
      w[0],
      "p.json /surfaces/0/spacing: the spacing 250 m of surface \"wp\" is larger than the surface "
      "(5 m x 3 m); "
      "luxgrid used one cell across it (spacings are in metres)");
  EXPECT_EQ(w[1],
            "p.json /surfaces/0: surface \"wp\": a grid of fewer than 3 x 3 points (1 x 1 points); "
            "luxgrid "
            "calculated it as "
            "given, but its Emin, U0 and map say little (use a smaller spacing)");
}

TEST(SanityChecks, AGridOfTwoRowsWarnsAndThreeDoesNot) {
  auto doc = lit_office();
  doc["surfaces"][0]["spacing"] = 1.5;  // 5 x 3 m: ceil(5/1.5) = 4 by ceil(3/1.5) = 2
  expect_one_warning(doc, {"p.json /surfaces/0: surface \"wp\": a grid", "(4 x 2 points)"});
  doc["surfaces"][0]["spacing"] = 1.0;  // 5 x 3 points
  EXPECT_EQ(warnings_of(doc), std::vector<std::string>{});
}

TEST(SanityChecks, RoomSurfacesNameTheirCoarseGrids) {
  auto doc = lit_office();
  doc["surfaces"].push_back(nlohmann::json::parse(
      R"({ "name": "room", "room_surfaces": { "room": "office" }, "spacing": 1.0 })"));
  // Floor and ceiling 6 x 4 points, long walls 6 x 3, short walls 4 x 3: all at least 3 x 3.
  EXPECT_EQ(warnings_of(doc), std::vector<std::string>{});
  doc["surfaces"][2]["spacing"] = 1.5;  // height 2.8 m: 2 rows on every wall
  expect_one_warning(doc, {"p.json /surfaces/2: surface \"room\": a grid",
                           "room wall 0 4 x 2 points", "room wall 3 3 x 2 points"});
}

TEST(SanityChecks, FluxInKilolumensWarns) {
  // The Mirel file gives 2632 lm; a flux of 4.4 klm written as 4.4 lm is a thousand times too dim.
  const std::string base = std::string(LUXGRID_SOURCE_DIR) + "/examples/office";
  auto doc = lit_office();
  doc["photometry"]["down"] = {{"file", "photometry/zumtobel_mirel_isym4.ldt"}, {"flux_lm", 4.4}};
  expect_one_warning(doc,
                     {"p.json /photometry/down/flux_lm: flux_lm 4.4 lm", "looks like kilolumens",
                      "luxgrid scaled the luminaire to 4.4 lm", "for 4400 lm write 4400"},
                     base);
  doc["photometry"]["down"]["flux_lm"] = 4400;  // a real value
  EXPECT_EQ(warnings_of(doc, base), std::vector<std::string>{});
}

TEST(SanityChecks, RotationsInRadiansWarnWholeDegreesDoNot) {
  auto doc = lit_office();
  doc["luminaires"][0]["rotation"] = {0, 0, 1.5708};
  expect_one_warning(
      doc, {"p.json /luminaires/0/rotation: the rotation [0, 0, 1.5708] looks like radians",
            "luxgrid reads degrees", "[0, 0, 90]"});
  doc["luminaires"][0]["rotation"] = {0, 0, 5};  // 5 degrees, whole: meant
  EXPECT_EQ(warnings_of(doc), std::vector<std::string>{});
  doc["luminaires"][0]["rotation"] = {0, 0, 0};
  EXPECT_EQ(warnings_of(doc), std::vector<std::string>{});
  doc["luminaires"][0]["rotation"] = {0, 0, 7.5};  // beyond a turn in radians: degrees
  EXPECT_EQ(warnings_of(doc), std::vector<std::string>{});
}

TEST(SanityChecks, ALuminaireAimedIntoANearbyWallWarns) {
  // 0.3 m from the west wall (x = 0), turned 90 deg about y: its nadir (-z) turns to -x, into
  // the wall 0.3 m away (wall 3 runs from corner 3 (0, 4) to corner 0 (0, 0)).
  auto doc = lit_office();
  doc["luminaires"][0]["position"] = {0.3, 2, 2.0};
  doc["luminaires"][0]["rotation"] = {0, 90, 0};
  expect_one_warning(
      doc, {"p.json /luminaires/0: panel: its main beam", "meets room \"office\" wall 3 0.3 m away",
            "luxgrid calculated it as placed and turned"});
  doc["luminaires"][0]["rotation"] = {0, -90, 0};  // the other way: across the room, 5.7 m
  EXPECT_EQ(warnings_of(doc), std::vector<std::string>{});
  doc["luminaires"][0]["rotation"] = {0, 0, 0};  // down: the floor, not a wall
  EXPECT_EQ(warnings_of(doc), std::vector<std::string>{});
}

TEST(SanityChecks, AnArrayNamesItsFirstMemberAimedIntoAWall) {
  auto doc = lit_office();
  doc["luminaires"][0] = nlohmann::json::parse(
      R"({ "name": "row", "photometry": "down", "rotation": [0, 90, 0],
           "array": { "origin": [0.2, 1, 2], "count": [2, 3], "spacing": [3, 1] } })");
  // The members at x = 0.2 (three of them) face the west wall 0.2 m away; those at 3.2 do not.
  expect_one_warning(doc,
                     {"p.json /luminaires/0: row [0,0] and 2 more of this entry: its main beam",
                      "wall 3 0.2 m away"});
}

TEST(SanityChecks, AGridFacingOutOfEveryRoomWarns) {
  // The south wall plane with u and v swapped: its normal (u x v) points to -y, out of the room.
  auto doc = lit_office();
  doc["surfaces"][1]["plane"]["u"] = {0, 0, 1};
  doc["surfaces"][1]["plane"]["v"] = {-1, 0, 0};
  expect_one_warning(
      doc,
      {"p.json /surfaces/1: surface \"south wall\": grid \"south wall\" faces out of every room"});
  // A plane outside every room (a facade outdoors) is not a mistake of this kind.
  doc["surfaces"][1]["plane"]["origin"] = {6, -5, 0};
  EXPECT_EQ(warnings_of(doc), std::vector<std::string>{});
}

TEST(SanityChecks, MainBeamOfAPointSymmetricSourceIsNone) {
  // Isotropic: no direction; Lambertian: straight down (-z), by symmetry.
  EXPECT_EQ(glm::length(main_beam_direction(photometry::IsotropicDistribution(100))), 0.0);
  const Vec3 d = main_beam_direction(photometry::LambertianDistribution(100));
  EXPECT_NEAR(d.z, -1.0, 1e-9);
}

}  // namespace
}  // namespace luxgrid::project
