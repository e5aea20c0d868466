// The project loader: good files load with the right values, bad files fail with one exact
// message naming the place.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "calc/scaled_distribution.h"
#include "geometry/polygon.h"
#include "project/project_file.h"
#include "project/project_limits.h"
#include "project_error.h"
#include "temp_folder.h"
#include "util/error.h"

namespace luxgrid::project {
using namespace calc;
namespace {

nlohmann::json minimal() {
  return nlohmann::json::parse(R"({
    "format": "luxgrid-project/1",
    "name": "t",
    "photometry": { "iso": { "builtin": "isotropic", "intensity_cd": 100 } },
    "rooms": [ { "name": "r", "outline": [[0,0],[4,0],[4,3],[0,3]], "height": 2.5 } ],
    "luminaires": [ { "photometry": "iso", "position": [2, 1.5, 2.5] } ],
    "surfaces": [ { "name": "wp", "workplane": { "room": "r", "height": 0.8, "border": 0.5 }, "spacing": 0.5 } ]
  })");
}

TEST(ProjectFile, MinimalProjectLoads) {
  const Scene s = parse_project(minimal(), "p.json", ".").scene;
  EXPECT_EQ(s.name, "t");
  ASSERT_EQ(s.luminaires.size(), 1u);
  EXPECT_EQ(s.luminaires[0].pose.position, Vec3(2, 1.5, 2.5));
  ASSERT_EQ(s.surfaces.size(), 1u);
  // 4 x 3 room, 0.5 border: 3 x 2 m at 0.5 m -> 6 x 4 cells, first centre at (0.75, 0.75, 0.8).
  EXPECT_EQ(s.surfaces[0].nu, 6);
  EXPECT_EQ(s.surfaces[0].nv, 4);
  EXPECT_EQ(s.surfaces[0].points.front(), Vec3(0.75, 0.75, 0.8));
  EXPECT_EQ(s.surfaces[0].points.back(), Vec3(3.25, 2.25, 0.8));
  EXPECT_EQ(s.settings.quality, Quality::standard);  // the default
}

TEST(ProjectFile, ArrayExpandsAlongXThenY) {
  auto doc = minimal();
  doc["luminaires"][0] = {
      {"photometry", "iso"},
      {"array", {{"origin", {1, 1, 2.5}}, {"count", {3, 2}}, {"spacing", {1.0, 0.5}}}}};
  const Scene s = parse_project(doc, "p.json", ".").scene;
  ASSERT_EQ(s.luminaires.size(), 6u);
  EXPECT_EQ(s.luminaires[1].pose.position, Vec3(2, 1, 2.5));
  EXPECT_EQ(s.luminaires[3].pose.position, Vec3(1, 1.5, 2.5));
  EXPECT_EQ(s.luminaires[5].label, "luminaire 0 [2,1]");
}

TEST(ProjectFile, SettingsAreRead) {
  auto doc = minimal();
  doc["settings"] = {{"quality", "draft"},
                     {"near_field", "never"},
                     {"indirect", "off"},
                     {"bounces", 3},
                     {"maintenance_factor", 0.8}};
  const Scene s = parse_project(doc, "p.json", ".").scene;
  EXPECT_EQ(s.settings.quality, Quality::draft);
  EXPECT_EQ(s.settings.near_field, NearFieldMode::never);
  EXPECT_EQ(s.settings.indirect, IndirectMode::off);
  EXPECT_EQ(s.settings.bounces, 3);
  EXPECT_DOUBLE_EQ(s.settings.maintenance_factor, 0.8);
}

TEST(ProjectFile, MaintenanceFactorFromItsCie97Parts) {
  // MF = LLMF x LSF x LMF x RSMF [CIE97]: 0.9 x 0.98 x 0.95 x 0.94 = 0.787626 (by hand).
  auto doc = minimal();
  doc["settings"] = {
      {"maintenance", {{"LLMF", 0.9}, {"LSF", 0.98}, {"LMF", 0.95}, {"RSMF", 0.94}}}};
  const Scene s = parse_project(doc, "p.json", ".").scene;
  EXPECT_NEAR(s.settings.maintenance_factor, 0.787626, 1e-15);
  ASSERT_TRUE(s.settings.maintenance_parts.has_value());
  EXPECT_EQ(s.settings.maintenance_parts->LSF, 0.98);
  // A plain number under the new key means the same as maintenance_factor.
  doc["settings"] = {{"maintenance", 0.7}};
  const Scene n = parse_project(doc, "p.json", ".").scene;
  EXPECT_EQ(n.settings.maintenance_factor, 0.7);
  EXPECT_FALSE(n.settings.maintenance_parts.has_value());
  // A missing factor is an error, not a silent 1.
  doc["settings"] = {{"maintenance", {{"LLMF", 0.9}, {"LSF", 0.98}, {"LMF", 0.95}}}};
  try {
    (void)parse_project(doc, "p.json", ".");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/settings/maintenance"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("RSMF"), std::string::npos) << e.what();
  }
  doc["settings"] = {{"maintenance", {{"LLMF", 0.0}, {"LSF", 1}, {"LMF", 1}, {"RSMF", 1}}}};
  EXPECT_THROW(parse_project(doc, "p.json", ".").scene, InputError);
}

TEST(ProjectFile, PlaneGridNormalIsUCrossV) {
  auto doc = minimal();
  doc["surfaces"][0] = nlohmann::json::parse(
      R"({"name": "wall", "plane": {"origin": [4,0,0], "u": [0,2,0], "v": [0,0,1], "size": [3, 2.5]}, "spacing": 1})");
  const Scene s = parse_project(doc, "p.json", ".").scene;
  const auto& g = s.surfaces[0];
  EXPECT_EQ(g.nu, 3);
  EXPECT_EQ(g.nv, 3);  // 2.5 m at <= 1 m -> 3 cells of 0.8333 m
  EXPECT_NEAR(g.spacing_v, 2.5 / 3, 1e-15);
  EXPECT_EQ(g.normals[0], Vec3(1, 0, 0));  // (0,1,0) x (0,0,1) = +x
  EXPECT_EQ(g.points[0], Vec3(4, 0.5, 2.5 / 6));
}

TEST(ProjectFile, AutoSpacingFollowsEn12464) {
  auto doc = minimal();
  doc["surfaces"][0]["spacing"] = "auto";
  const Scene s = parse_project(doc, "p.json", ".").scene;
  // Longer side d = 3 m: p = 0.2 * 5^log10(3) = 0.2 * 2.1555 = 0.4311 m -> ceil(3 / 0.4311) = 7.
  EXPECT_EQ(s.surfaces[0].nu, 7);
  EXPECT_EQ(s.surfaces[0].nv, 5);  // 2 m / 0.4311 = 4.64 -> 5
}

struct BadCase {
  const char* name;
  const char* pointer;   // JSON pointer to patch (RFC 6902 "add"/"replace" path)
  const char* value;     // JSON text to put there
  const char* expected;  // the exact message
};

class ProjectFileBad : public ::testing::TestWithParam<BadCase> {};

TEST_P(ProjectFileBad, ExactMessage) {
  const auto& c = GetParam();
  auto doc = minimal();
  doc[nlohmann::json::json_pointer(c.pointer)] = nlohmann::json::parse(c.value);
  EXPECT_EQ(error_of(doc), c.expected);
}

INSTANTIATE_TEST_SUITE_P(
    Messages, ProjectFileBad,
    ::testing::Values(
        BadCase{"unknown_top_key", "/reflectence", "1",
                "p.json /reflectence: unknown key \"reflectence\" (expected one of: daylight, "
                "format, luminaires, name, openings, photometry, rooms, settings, surfaces)"},
        BadCase{"wrong_format", "/format", "\"luxgrid-project/2\"",
                "p.json /format: expected \"luxgrid-project/1\", got \"luxgrid-project/2\""},
        BadCase{"rotation_two_numbers", "/luminaires/0/rotation", "[0, 90]",
                "p.json /luminaires/0/rotation: expected 3 numbers, got 2"},
        BadCase{"rotation_empty", "/luminaires/0/rotation", "[]",
                "p.json /luminaires/0/rotation: expected 3 numbers, got 0"},
        BadCase{"position_string", "/luminaires/0/position", "\"here\"",
                "p.json /luminaires/0/position: expected 3 numbers, got a string"},
        BadCase{"position_item_type", "/luminaires/0/position", "[1, \"2\", 3]",
                "p.json /luminaires/0/position/1: expected a number, got a string"},
        BadCase{"negative_height", "/rooms/0/height", "-2.5",
                "p.json /rooms/0/height: expected a positive number, got -2.5"},
        BadCase{"reflectance_above_one", "/rooms/0/reflectance", "{\"walls\": 1.2}",
                "p.json /rooms/0/reflectance/walls: expected a number in [0, 1], got 1.2"},
        BadCase{"reflectance_unknown", "/rooms/0/reflectance", "{\"wall\": 0.5}",
                "p.json /rooms/0/reflectance/wall: unknown key \"wall\" (expected one of: ceiling, "
                "floor, walls)"},
        BadCase{"empty_outline", "/rooms/0/outline", "[]",
                "p.json /rooms/0/outline: expected at least 3 corners, got 0"},
        BadCase{"unknown_photometry", "/luminaires/0/photometry", "\"panel\"",
                "p.json /luminaires/0/photometry: no photometry entry named \"panel\""},
        BadCase{"negative_spacing", "/surfaces/0/spacing", "-0.25",
                "p.json /surfaces/0/spacing: expected a positive number, got -0.25"},
        BadCase{"negative_emitter_size", "/luminaires/0/emitter",
                "{\"shape\": \"rectangle\", \"size\": [0.6, -0.6]}",
                "p.json /luminaires/0/emitter/size: expected two positive sizes in metres"},
        BadCase{"unknown_builtin", "/photometry/iso/builtin", "\"spot\"",
                "p.json /photometry/iso/builtin: expected \"isotropic\" or \"lambertian\", got "
                "\"spot\""},
        BadCase{"missing_file", "/photometry/iso", "\"no/such/file.ies\"",
                "p.json /photometry/iso: photometry file not found: no/such/file.ies"},
        BadCase{"bad_quality", "/settings", "{\"quality\": \"best\"}",
                "p.json /settings/quality: expected \"draft\", \"standard\", \"high\" or "
                "\"reference\", got \"best\""},
        BadCase{
            "bounces_zero", "/settings", "{\"bounces\": 0}",
            "p.json /settings/bounces: expected \"auto\" or a whole number from 1 to 1000, got 0"},
        BadCase{"bounces_billion", "/settings", "{\"bounces\": 1e9}",
                "p.json /settings/bounces: expected \"auto\" or a whole number from 1 to 1000, got "
                "1000000000.0"},
        BadCase{"array_10000_by_10000", "/luminaires/0",
                "{\"photometry\": \"iso\", \"array\": {\"origin\": [0,0,2], \"count\": [10000, "
                "10000], \"spacing\": [0.1, 0.1]}}",
                "p.json /luminaires/0/array/count: the array has 100000000 luminaires, more than "
                "the limit of 20000 in a project"},
        BadCase{"array_count_above_limit", "/luminaires/0",
                "{\"photometry\": \"iso\", \"array\": {\"origin\": [0,0,2], \"count\": [10001, 1], "
                "\"spacing\": [0.1, 0.1]}}",
                "p.json /luminaires/0/array/count/0: expected a count from 1 to 10000"},
        BadCase{"luminaires_in_total", "/luminaires/1",
                "{\"photometry\": \"iso\", \"array\": {\"origin\": [0,0,2], \"count\": [200, 100], "
                "\"spacing\": [0.01, 0.01]}}",
                "p.json /luminaires/1/array/count: the project would have 20001 luminaires, more "
                "than the limit of 20000"},
        BadCase{"array_beyond_coordinates", "/luminaires/0",
                "{\"photometry\": \"iso\", \"array\": {\"origin\": [0,0,2], \"count\": [10000, 1], "
                "\"spacing\": [100, 1]}}",
                "p.json /luminaires/0/array/spacing: the array reaches x = 999900 m, beyond the "
                "limit of 100000 m for coordinates"},
        BadCase{"position_far_away", "/luminaires/0/position", "[1e6, 0, 2]",
                "p.json /luminaires/0/position/0: 1e+06 m is beyond the limit of 100000 m for "
                "coordinates and lengths"},
        BadCase{"outline_far_away", "/rooms/0/outline/2", "[4, -3e5]",
                "p.json /rooms/0/outline/2/1: -300000 m is beyond the limit of 100000 m for "
                "coordinates and lengths"},
        BadCase{"room_too_high", "/rooms/0/height", "1e300",
                "p.json /rooms/0/height: 1e+300 m is beyond the limit of 100000 m for coordinates "
                "and lengths"},
        BadCase{"spacing_1e_300", "/surfaces/0/spacing", "1e-300",
                "p.json /surfaces/0: the grid would have over 1e308 points, more than the limit of "
                "4000000; use a larger spacing"},
        BadCase{"spacing_1e_100", "/surfaces/0/spacing", "1e-100",
                "p.json /surfaces/0: the grid would have 6e+200 points, more than the limit of "
                "4000000; use a larger spacing"},
        BadCase{"emitter_one_nanometre", "/luminaires/0/emitter",
                "{\"shape\": \"disk\", \"diameter\": 1e-9}",
                "p.json /luminaires/0/emitter/diameter: expected an emitter size from 0.001 to "
                "1000 m, got 1e-09 m (a smaller source is a \"point\")"},
        BadCase{"emitter_two_kilometres", "/luminaires/0/emitter",
                "{\"shape\": \"rectangle\", \"size\": [0.6, 2000]}",
                "p.json /luminaires/0/emitter/size/1: expected an emitter size from 0.001 to 1000 "
                "m, got 2000 m (a smaller source is a \"point\")"},
        BadCase{"builtin_too_bright", "/photometry/iso/intensity_cd", "1e12",
                "p.json /photometry/iso/intensity_cd: expected at most 1e+09 cd (the intensity "
                "limit), got 1e+12"},
        BadCase{"surface_name_too_long", "/surfaces/0/name",
                "\"xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx"
                "xxxxxxxxxxxxxxxxxxxxx\"",
                "p.json /surfaces/0/name: the surface name is 101 characters long, more than the "
                "limit of 100 (it names the surface's output files)"},
        BadCase{"hidden_output_file", "/surfaces/0/name", "\".wp\"",
                "p.json /surfaces/0/name: surface \".wp\" would write the hidden file .wp.csv; "
                "start its name with a letter or digit"},
        BadCase{"absolute_photometry_path", "/photometry/iso", "\"/etc/passwd\"",
                "p.json /photometry/iso: the photometry file /etc/passwd lies outside the project "
                "folder; to allow it, set \"settings\": {\"allow_files_outside_project\": true}"},
        BadCase{
            "photometry_path_climbs_out", "/photometry/iso", "{\"file\": \"../../x.ies\"}",
            "p.json /photometry/iso/file: the photometry file ../../x.ies lies outside the project "
            "folder; to allow it, set \"settings\": {\"allow_files_outside_project\": true}"},
        BadCase{"unknown_room", "/surfaces/0/workplane/room", "\"hall\"",
                "p.json /surfaces/0/workplane/room: no room named \"hall\""},
        BadCase{
            "border_too_wide", "/surfaces/0/workplane/border", "1.5",
            "p.json /surfaces/0/workplane/border: the border leaves no workplane inside the room"},
        BadCase{"huge_grid", "/surfaces/0/spacing", "0.0001",
                "p.json /surfaces/0: the grid would have 600000000 points, more than the limit of "
                "4000000; use a larger spacing"},
        BadCase{"self_intersecting_outline", "/rooms/0/outline", "[[0,0],[4,3],[4,0],[0,3]]",
                "p.json /rooms/0/outline: room \"r\": the outline crosses itself (edge 0-1 meets "
                "edge 2-3)"},
        BadCase{"zero_area_outline", "/rooms/0/outline", "[[0,0],[2,0],[4,0]]",
                "p.json /rooms/0/outline: room \"r\": the outline has zero area"},
        BadCase{"repeated_corner", "/rooms/0/outline", "[[0,0],[4,0],[4,0],[0,3]]",
                "p.json /rooms/0/outline: room \"r\": corners 1 and 2 coincide"},
        BadCase{"box_min_above_max", "/rooms/0/obstacles",
                "[{\"name\": \"cabinet\", \"box\": {\"min\": [1,1,1.8], \"max\": [2,2,0]}}]",
                "p.json /rooms/0/obstacles/0/box: obstacle \"cabinet\": box min must be below max "
                "in x, y and z, got z from 1.8 to 0"},
        BadCase{"box_flat", "/rooms/0/obstacles",
                "[{\"box\": {\"min\": [1,1,0], \"max\": [1,2,1]}}]",
                "p.json /rooms/0/obstacles/0/box: obstacle \"obstacle 0\": box min must be below "
                "max in x, y and z, got x from 1 to 1"},
        BadCase{"obstacle_outside", "/rooms/0/obstacles",
                "[{\"name\": \"shed\", \"box\": {\"min\": [5,0,0], \"max\": [6,1,2]}}]",
                "p.json /rooms/0/obstacles/0: obstacle \"shed\" lies outside room \"r\""},
        BadCase{"obstacle_above_ceiling", "/rooms/0/obstacles",
                "[{\"name\": \"lamp\", \"box\": {\"min\": [1,1,2.5], \"max\": [2,2,3]}}]",
                "p.json /rooms/0/obstacles/0: obstacle \"lamp\" lies outside room \"r\""},
        BadCase{"obstacle_box_and_prism", "/rooms/0/obstacles",
                "[{\"box\": {\"min\": [1,1,0], \"max\": [2,2,1]}, \"prism\": {}}]",
                "p.json /rooms/0/obstacles/0: expected exactly one of \"box\" or \"prism\""},
        BadCase{"prism_self_intersecting", "/rooms/0/obstacles",
                "[{\"name\": \"x\", \"prism\": {\"outline\": [[1,1],[2,2],[2,1],[1,2]], \"z0\": 0, "
                "\"z1\": 1}}]",
                "p.json /rooms/0/obstacles/0/prism/outline: obstacle \"x\": the outline crosses "
                "itself (edge 0-1 meets edge 2-3)"},
        BadCase{"obstacle_unknown_key", "/rooms/0/obstacles",
                "[{\"box\": {\"min\": [1,1,0], \"max\": [2,2,1], \"rotation\": 30}}]",
                "p.json /rooms/0/obstacles/0/box/rotation: unknown key \"rotation\" (expected one "
                "of: max, min, rotation_z)"},
        BadCase{"zero_size_plane", "/surfaces/0",
                "{\"name\": \"w\", \"plane\": {\"origin\": [0,0,0], \"u\": [1,0,0], \"v\": "
                "[0,0,1], \"size\": [0, 2]}, \"spacing\": 0.5}",
                "p.json /surfaces/0/plane/size: expected two positive sizes in metres"},
        BadCase{"zero_spacing", "/surfaces/0/spacing", "0",
                "p.json /surfaces/0/spacing: expected a positive number, got 0"},
        BadCase{"bad_quantity", "/surfaces/0/quantity", "\"semicylindrical\"",
                "p.json /surfaces/0/quantity: expected \"planar\", \"horizontal\", \"vertical\", "
                "\"cylindrical\" or \"semi-cylindrical\", got \"semicylindrical\""},
        BadCase{"vertical_without_facing", "/surfaces/0/quantity", "\"vertical\"",
                "p.json /surfaces/0/quantity: a vertical quantity on a horizontal surface needs "
                "\"facing\": [x, y]"},
        BadCase{"facing_without_vertical", "/surfaces/0/facing", "[1, 0]",
                "p.json /surfaces/0/facing: \"facing\" only goes with \"quantity\": \"vertical\" "
                "or \"semi-cylindrical\""},
        BadCase{"semi_cylindrical_without_facing", "/surfaces/0/quantity", "\"semi-cylindrical\"",
                "p.json /surfaces/0/quantity: a semi-cylindrical quantity on a horizontal surface "
                "needs \"facing\": [x, y]"},
        BadCase{"position_and_array", "/luminaires/0/array",
                "{\"origin\": [0,0,0], \"count\": [1,1], \"spacing\": [1,1]}",
                "p.json /luminaires/0: expected exactly one of \"position\" or \"array\""}),
    [](const auto& info) { return std::string(info.param.name); });

nlohmann::json l_room() {
  auto doc = minimal();
  doc["rooms"][0] = nlohmann::json::parse(R"({
    "name": "r", "outline": [[0,0],[6,0],[6,3],[3,3],[3,6],[0,6]], "height": 3,
    "obstacles": [
      { "name": "column", "box": { "min": [1.5, 1.5, 0], "max": [2.5, 2.5, 3] }, "reflectance": 0.4 },
      { "name": "table", "box": { "min": [0.6, 0.6, 0], "max": [1.4, 1.4, 0.7] } },
      { "name": "partition", "prism": { "outline": [[4,0],[4,1],[4.1,1],[4.1,0]], "z0": 0, "z1": 2 } }
    ] })");
  doc["surfaces"][0] = nlohmann::json::parse(
      R"({ "name": "wp", "workplane": { "room": "r", "height": 0.8, "border": 0.5 }, "spacing": 1 })");
  return doc;
}

TEST(ProjectFile, LShapedRoomWithObstacles) {
  const Scene s = parse_project(l_room(), "p.json", ".").scene;
  ASSERT_EQ(s.rooms[0].obstacles.size(), 3u);
  EXPECT_EQ(s.rooms[0].obstacles[1].name, "table");
  EXPECT_DOUBLE_EQ(s.rooms[0].obstacles[1].reflectance, 0.5);  // the default
  EXPECT_DOUBLE_EQ(s.rooms[0].obstacles[0].z1, 3.0);
  // The clockwise prism outline was reversed, with a warning.
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_EQ(s.warnings[0].text(),
            "p.json /rooms/0/obstacles/2/prism/outline: obstacle \"partition\": the outline is "
            "clockwise; reversed to counter-clockwise");
  // Inset L: 5 x 5 cells of 1 m; 16 inside the L, (2, 2) inside the column; the table (0.7 m)
  // and the partition (its footprint holds no cell centre) remove nothing.
  const auto& g = s.surfaces[0];
  EXPECT_EQ(g.nu, 5);
  EXPECT_EQ(g.nv, 5);
  EXPECT_EQ(g.points_outside, 9u);
  EXPECT_EQ(g.points_in_obstacles, 1u);
  EXPECT_FALSE(g.active[6]);
}

TEST(ProjectFile, ClockwiseRoomIsReversedWithAWarning) {
  auto doc = minimal();
  doc["rooms"][0]["outline"] = nlohmann::json::parse("[[0,3],[4,3],[4,0],[0,0]]");
  const Scene s = parse_project(doc, "p.json", ".").scene;
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_EQ(s.warnings[0].text(),
            "p.json /rooms/0/outline: room \"r\": the outline is clockwise; reversed to "
            "counter-clockwise");
  EXPECT_GT(geometry::signed_area(s.rooms[0].outline), 0.0);
  EXPECT_EQ(s.surfaces[0].points.front(), Vec3(0.75, 0.75, 0.8));  // the same grid as CCW
}

TEST(ProjectFile, LuminaireOutsideEveryRoomOrInsideAnObstacleWarns) {
  auto doc = l_room();
  doc["luminaires"][0]["position"] = {5, 5, 2.9};  // in the missing quadrant of the L
  doc["luminaires"].push_back(
      {{"name", "in column"}, {"photometry", "iso"}, {"position", {2, 2, 2}}});
  const Scene s = parse_project(doc, "p.json", ".").scene;
  ASSERT_EQ(s.warnings.size(), 3u);
  EXPECT_EQ(s.warnings[1].text(), "p.json /luminaires/0: luminaire 0: outside every room");
  EXPECT_EQ(s.warnings[2].text(),
            "p.json /luminaires/1: in column: inside obstacle \"column\" of room \"r\"");
}

TEST(ProjectFile, RoomSurfacesGiveOneGridPerFace) {
  auto doc = l_room();
  doc["surfaces"][0] =
      nlohmann::json::parse(R"({ "name": "L", "room_surfaces": { "room": "r" }, "spacing": 0.5 })");
  const Scene s = parse_project(doc, "p.json", ".").scene;
  ASSERT_EQ(s.surfaces.size(), 8u);  // floor, ceiling, 6 walls
  const auto& floor = s.surfaces[0];
  EXPECT_EQ(floor.name, "L floor");
  // 12 x 12 cells of 0.5 m over the 6 x 6 box; the L holds 27 / 0.25 = 108 of them. On the floor
  // the column (1.5..2.5) holds the centres 1.75, 2.25 in x and y (4) and the 0.7 m table
  // (0.6..1.4) holds 0.75, 1.25 (4); the thin partition holds none.
  EXPECT_EQ(floor.nu, 12);
  EXPECT_EQ(floor.points_outside, 36u);
  EXPECT_EQ(floor.points_in_obstacles, 8u);
  // The ceiling (z = 3) is reached only by the column.
  EXPECT_EQ(s.surfaces[1].points_in_obstacles, 4u);
  EXPECT_EQ(s.surfaces[2].name, "L wall 0");
  EXPECT_EQ(s.surfaces[2].nu, 12);
  EXPECT_EQ(s.surfaces[2].nv, 6);
  EXPECT_EQ(s.surfaces[7].name, "L wall 5");
}

TEST(ProjectFile, QuantitiesSetReceiverNormals) {
  auto doc = minimal();
  doc["surfaces"][0]["quantity"] = "vertical";
  doc["surfaces"][0]["facing"] = {0, -2};
  Scene s = parse_project(doc, "p.json", ".").scene;
  EXPECT_EQ(s.surfaces[0].quantity, geometry::Quantity::vertical);
  EXPECT_EQ(s.surfaces[0].normals[0], Vec3(0, -1, 0));
  doc["surfaces"][0].erase("facing");
  doc["surfaces"][0]["quantity"] = "cylindrical";
  s = parse_project(doc, "p.json", ".").scene;
  EXPECT_EQ(s.surfaces[0].quantity, geometry::Quantity::cylindrical);
  EXPECT_EQ(s.surfaces[0].normals[0], Vec3(0, 0, 1));
  // A half cylinder faces `facing` (normalised): the loader stores it as every point's normal.
  doc["surfaces"][0]["quantity"] = "semi-cylindrical";
  doc["surfaces"][0]["facing"] = {3, 4};
  s = parse_project(doc, "p.json", ".").scene;
  EXPECT_EQ(s.surfaces[0].quantity, geometry::Quantity::semi_cylindrical);
  EXPECT_NEAR(s.surfaces[0].normals[0].x, 0.6, 1e-15);
  EXPECT_NEAR(s.surfaces[0].normals[0].y, 0.8, 1e-15);
  EXPECT_EQ(s.surfaces[0].normals[0].z, 0.0);
  doc["surfaces"][0].erase("facing");
  // A wall plane asked for vertical illuminance keeps its own horizontal normal u x v = +x.
  doc["surfaces"][0] = nlohmann::json::parse(
      R"({"name": "wall", "plane": {"origin": [4,0,0], "u": [0,1,0], "v": [0,0,1], "size": [3, 2.5]}, "spacing": 1, "quantity": "vertical"})");
  s = parse_project(doc, "p.json", ".").scene;
  EXPECT_EQ(s.surfaces[0].normals[0], Vec3(1, 0, 0));
}

TEST(ProjectFile, MalformedJsonNamesLineAndColumn) {
  const testing_support::TempFolder dir;
  const auto file =
      dir.write("broken.json",
                "{\n  \"format\": \"luxgrid-project/1\",\n  \"name\": \"x\"\n  \"rooms\": []\n}\n");
  try {
    (void)load_project(file);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    // nlohmann stops at the end of the offending token: the "rooms" string ending in column 9.
    EXPECT_EQ(msg, file.string() +
                       ":4:9: malformed JSON: syntax error while parsing object - "
                       "unexpected string literal; expected '}'");
  }
}

// A small plane surface named `name` (1 point).
nlohmann::json plane_surface(const std::string& name) {
  return {{"name", name},
          {"plane", {{"origin", {0, 0, 0}}, {"u", {1, 0, 0}}, {"v", {0, 1, 0}}, {"size", {1, 1}}}},
          {"spacing", 1}};
}

std::string error_with_surfaces(const std::vector<std::string>& names) {
  auto doc = minimal();
  doc["surfaces"] = nlohmann::json::array();
  for (const auto& n : names) doc["surfaces"].push_back(plane_surface(n));
  return error_of(doc);
}

const char* kRenameHint =
    " also writes (output file names ignore case and turn characters other than letters, digits, "
    "'-', '_' and '.' into '_'); rename one of them";

TEST(ProjectFile, SurfacesWritingTheSameFileAreRefused) {
  EXPECT_EQ(
      error_with_surfaces({"a/b", "a_b"}),
      std::string(
          "p.json /surfaces/1/name: surface \"a_b\" would write a_b.csv, which surface \"a/b\"") +
          kRenameHint);
  // x's direct-light plot is x_direct.png, the plot of a surface named x_direct.
  EXPECT_EQ(error_with_surfaces({"x", "x_direct"}),
            std::string("p.json /surfaces/1/name: surface \"x_direct\" would write x_direct.png, "
                        "which surface \"x\"") +
                kRenameHint);
  // Case-insensitive file systems (macOS, Windows) make Hall.csv and hall.csv one file.
  EXPECT_EQ(error_with_surfaces({"Hall", "hall"}),
            std::string("p.json /surfaces/1/name: surface \"hall\" would write hall.csv, which "
                        "surface \"Hall\"") +
                kRenameHint);
  EXPECT_EQ(error_with_surfaces({"a b", "a-b", "a.b", "ab"}), "(no error)");
}

TEST(ProjectFile, RoomSurfaceGridsAreCheckedForCollisionsAndLength) {
  auto doc = minimal();
  doc["surfaces"] =
      nlohmann::json::array({plane_surface("R FLOOR"),
                             {{"name", "r"}, {"room_surfaces", {{"room", "r"}}}, {"spacing", 1}}});
  EXPECT_EQ(error_of(doc), std::string("p.json /surfaces/1/name: surface \"r floor\" would write "
                                       "r_floor.csv, which surface \"R FLOOR\"") +
                               kRenameHint);
  // 95 characters are fine for the entry, but its first grid, "<name> floor", has 101.
  doc["surfaces"] = nlohmann::json::array(
      {{{"name", std::string(95, 'r')}, {"room_surfaces", {{"room", "r"}}}, {"spacing", 1}}});
  EXPECT_EQ(error_of(doc),
            "p.json /surfaces/0/name: the surface name is 101 characters long, more than "
            "the limit of 100 (it names the surface's output files)");
}

TEST(ProjectFile, RoomAndObstacleCountsAreCheckedBeforeBuilding) {
  auto doc = minimal();
  doc["rooms"] = nlohmann::json::array();
  for (size_t k = 0; k <= kMaxRooms; ++k) doc["rooms"].push_back(nullptr);
  EXPECT_EQ(error_of(doc), "p.json /rooms: 1001 rooms, more than the limit of 1000");
  doc = minimal();
  doc["rooms"][0]["obstacles"] = nlohmann::json::array();
  for (size_t k = 0; k <= kMaxObstacles; ++k) doc["rooms"][0]["obstacles"].push_back(nullptr);
  EXPECT_EQ(error_of(doc),
            "p.json /rooms/0/obstacles: the project would have 10001 obstacles, more than the "
            "limit of 10000");
}

TEST(ProjectFile, OutlineSurfaceAndPhotometryCountsAreLimited) {
  auto doc = minimal();
  doc["rooms"][0]["outline"] = nlohmann::json::array();
  for (size_t k = 0; k <= kMaxOutlineCorners; ++k) doc["rooms"][0]["outline"].push_back({k, 0});
  EXPECT_EQ(error_of(doc), "p.json /rooms/0/outline: 1001 corners, more than the limit of 1000");
  doc = minimal();
  for (size_t k = 0; k < kMaxSurfaces; ++k) doc["surfaces"].push_back(nullptr);
  EXPECT_EQ(error_of(doc), "p.json /surfaces: 1001 surfaces, more than the limit of 1000");
  doc = minimal();
  for (size_t k = 0; k < kMaxPhotometryEntries; ++k)
    doc["photometry"]["p" + std::to_string(k)] = nullptr;
  EXPECT_EQ(error_of(doc),
            "p.json /photometry: 1001 photometry entries, more than the limit of 1000");
}

TEST(ProjectFile, LuminairePointPairsAreLimited) {
  auto doc = minimal();
  // 20 000 luminaires (the limit) and a 224 x 224 m plane at 1 m: 50 176 points.
  doc["luminaires"][0] = {
      {"photometry", "iso"},
      {"array", {{"origin", {0, 0, 2}}, {"count", {200, 100}}, {"spacing", {0.01, 0.01}}}}};
  doc["surfaces"][0] = plane_surface("big");
  doc["surfaces"][0]["plane"]["size"] = {224, 224};
  EXPECT_EQ(error_of(doc),
            "p.json /surfaces/0: 20000 luminaires x 50176 points = 1.00352e+09 luminaire-point "
            "pairs, more than the limit of 1e+09; use fewer luminaires or larger spacings");
  doc["surfaces"][0]["plane"]["size"] = {250, 200};  // 50 000 points: exactly at the limit
  EXPECT_EQ(error_of(doc), "(no error)");
}

TEST(ProjectFile, DeeplyNestedUnknownKeyFailsWithoutCrashing) {
  // The measured segfault: 100 000 nested objects under an unknown key.
  std::string text = R"({"format": "luxgrid-project/1", "extra": )";
  const size_t prefix = text.size();
  for (int i = 0; i < 100000; ++i) text += "{\"a\":";
  text += "1" + std::string(100000, '}') + "}";
  try {
    (void)parse_project_text(text, "p.json", ".");
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "p.json:1:" + std::to_string(prefix + 63 * 5 + 1) +
                  ": objects and arrays nested deeper than the limit of 64 levels");
  }
}

TEST(ProjectFile, DuplicateLuminairesKeyIsAnError) {
  // Last-wins used to give `"luminaires": []`: 0 lx and exit 0.
  std::string text = minimal().dump();
  text.insert(text.size() - 1, ",\n\"luminaires\": []");
  try {
    (void)parse_project_text(text, "p.json", ".");
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "p.json:2:12 /luminaires: duplicate key \"luminaires\" (first given on line 1)");
  }
}

// A small absolute IES file: peak 1000 cd at nadir, 3 vertical angles, one C plane.
std::string small_ies(const std::string& version_tag = "IESNA:LM-63-2002") {
  return version_tag + "\nTILT=NONE\n1 -1 1 3 1 1 2 0 0 0\n1 1 100\n0 45 90\n0\n1000 800 0\n";
}

nlohmann::json with_file_photometry(const nlohmann::json& entry) {
  auto doc = minimal();
  doc["photometry"]["lamp"] = entry;
  doc["luminaires"][0]["photometry"] = "lamp";
  return doc;
}

std::string error_in(const nlohmann::json& doc, const std::filesystem::path& base_dir) {
  try {
    (void)parse_project(doc, "p.json", base_dir);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ProjectFile, MultiplierAndFluxMayNotScaleBeyondTheIntensityLimit) {
  const testing_support::TempFolder dir;
  dir.write("lamp.ies", small_ies());
  EXPECT_EQ(
      error_in(with_file_photometry({{"file", "lamp.ies"}, {"multiplier", 1e7}}), dir.path()),
      "p.json /photometry/lamp/multiplier: the peak intensity would be 1e+10 cd (1000 cd x 1e+07), "
      "more than the limit of 1e+09 cd");
  // At the limit exactly it loads.
  EXPECT_EQ(error_in(with_file_photometry({{"file", "lamp.ies"}, {"multiplier", 1e6}}), dir.path()),
            "(no error)");
  // flux_lm: the factor is the target over the distribution's own flux.
  const Scene plain = parse_project(with_file_photometry("lamp.ies"), "p.json", dir.path()).scene;
  const double flux = luminous_flux(*plain.photometry.at("lamp").distribution);
  char factor[32];
  std::snprintf(factor, sizeof factor, "%g", 1e15 / flux);
  char peak[32];
  std::snprintf(peak, sizeof peak, "%g", 1000 * (1e15 / flux));
  EXPECT_EQ(error_in(with_file_photometry({{"file", "lamp.ies"}, {"flux_lm", 1e15}}), dir.path()),
            std::string("p.json /photometry/lamp/flux_lm: the peak intensity would be ") + peak +
                " cd (1000 cd x " + factor + "), more than the limit of 1e+09 cd");
}

TEST(ProjectFile, PhotometryWarningsReachTheSceneOncePerEntry) {
  const testing_support::TempFolder dir;
  dir.write("old.ies", small_ies("IESNA95"));
  auto doc = with_file_photometry("old.ies");
  doc["photometry"]["again"] = "old.ies";
  const Scene s = parse_project(doc, "p.json", dir.path()).scene;
  const auto& file_warnings = s.photometry.at("lamp").warnings;
  ASSERT_EQ(file_warnings.size(), 1u);
  ASSERT_EQ(s.warnings.size(), 2u);
  // Entries in key order (std::map): "again", then "lamp".
  EXPECT_EQ(s.warnings[0].text(), "p.json /photometry/again: " + file_warnings[0]);
  EXPECT_EQ(s.warnings[1].text(), "p.json /photometry/lamp: " + file_warnings[0]);
}

TEST(ProjectFile, PhotometryOutsideTheProjectFolderNeedsTheSetting) {
  const testing_support::TempFolder dir;
  dir.write("shared/lamp.ies", small_ies());
  const auto project_dir = dir.path() / "project";
  std::filesystem::create_directories(project_dir / "sub");
  const auto doc = with_file_photometry("../shared/lamp.ies");
  EXPECT_EQ(error_in(doc, project_dir),
            "p.json /photometry/lamp: the photometry file ../shared/lamp.ies lies outside the "
            "project folder; "
            "to allow it, set \"settings\": {\"allow_files_outside_project\": true}");
  const std::string absolute = (dir.path() / "shared/lamp.ies").string();
  EXPECT_EQ(error_in(with_file_photometry(absolute), project_dir),
            "p.json /photometry/lamp: the photometry file " + absolute +
                " lies outside the project folder; "
                "to allow it, set \"settings\": {\"allow_files_outside_project\": true}");
  // A ../ that stays inside the tree is fine.
  dir.write("project/lamp.ies", small_ies());
  EXPECT_EQ(error_in(with_file_photometry("sub/../lamp.ies"), project_dir), "(no error)");
  // With the setting, both load.
  auto allowed = doc;
  allowed["settings"] = {{"allow_files_outside_project", true}};
  EXPECT_EQ(parse_project(allowed, "p.json", project_dir).scene.photometry.at("lamp").source,
            "../shared/lamp.ies");
  allowed["photometry"]["lamp"] = absolute;
  EXPECT_EQ(parse_project(allowed, "p.json", project_dir).scene.photometry.at("lamp").source,
            absolute);
}

TEST(ProjectFile, LoadProjectReadsThroughTheSafeParse) {
  const testing_support::TempFolder dir;
  std::string text = minimal().dump();
  const auto file = dir.write("p.json", text);
  EXPECT_EQ(load_project(file).scene.name, "t");
  text.insert(text.size() - 1, R"(,"name": "u")");
  const auto dup = dir.write("dup.json", text);
  try {
    (void)load_project(dup);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    const size_t closing_quote = text.rfind("\"name\"") + 5;
    EXPECT_EQ(std::string(e.what()), dup.string() + ":1:" + std::to_string(closing_quote + 1) +
                                         " /name: duplicate key \"name\" (first given on line 1)");
  }
}

}  // namespace
}  // namespace luxgrid::project
