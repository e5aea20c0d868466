// Per-room candidate luminaires (calc/direct_reach.h): a point tests only the luminaires whose
// opening touches one of its rooms, and gets exactly the illuminance it gets from testing every
// luminaire through the whole scene's visibility tree.
//
// Three 4 x 4 x 3 m rooms: A = [0,4] x [0,4] and B = [4,8] x [0,4] share the wall x = 4, C =
// [8.2,12] x [0,4] stands 0.2 m apart. A 1 x 1 m Lambertian panel in each ceiling's middle
// (luminaires 0, 1, 2), and a 0.6 x 0.6 m panel at x = 3.9 in A whose opening reaches 0.2 m
// through the shared wall into B (luminaire 3).
#include <gtest/gtest.h>

#include "calc/direct.h"
#include "calc/direct_reach.h"
#include "calc/plan.h"
#include "project/project_file.h"

namespace luxgrid::calc {
namespace {

Scene three_rooms() {
  return project::parse_project(nlohmann::json::parse(R"({
    "format": "luxgrid-project/1",
    "settings": { "quality": "standard", "indirect": "off", "near_field": "auto" },
    "photometry": { "panel": { "builtin": "lambertian", "intensity_cd": 1000 } },
    "rooms": [
      { "name": "A", "outline": [[0,0],[4,0],[4,4],[0,4]], "height": 3,
        "reflectance": { "floor": 0, "walls": 0, "ceiling": 0 } },
      { "name": "B", "outline": [[4,0],[8,0],[8,4],[4,4]], "height": 3,
        "reflectance": { "floor": 0, "walls": 0, "ceiling": 0 } },
      { "name": "C", "outline": [[8.2,0],[12,0],[12,4],[8.2,4]], "height": 3,
        "reflectance": { "floor": 0, "walls": 0, "ceiling": 0 } } ],
    "luminaires": [
      { "photometry": "panel", "position": [2, 2, 3], "emitter": { "shape": "rectangle", "size": [1, 1] } },
      { "photometry": "panel", "position": [6, 2, 3], "emitter": { "shape": "rectangle", "size": [1, 1] } },
      { "photometry": "panel", "position": [10, 2, 3], "emitter": { "shape": "rectangle", "size": [1, 1] } },
      { "photometry": "panel", "position": [3.9, 1, 3], "emitter": { "shape": "rectangle", "size": [0.6, 0.6] } } ],
    "surfaces": [ { "name": "probes", "points": [
      { "at": [1, 1, 0.8], "normal": [0, 0, 1] },
      { "at": [5, 1, 0.8], "normal": [0, 0, 1] },
      { "at": [4.3, 1, 0.8], "normal": [0, 0, 1] },
      { "at": [10, 3, 0.8], "normal": [0, 0, 1] },
      { "at": [4, 2, 1.5], "normal": [1, 0, 0] },
      { "at": [4, 2, 1.5], "normal": [-1, 0, 0] },
      { "at": [8.2, 2, 1.5], "normal": [1, 0, 0] },
      { "at": [8.1, 2, 1.5], "normal": [-1, 0, 0] },
      { "at": [8.1, 2, 3.5], "normal": [0, 0, -1] } ] } ]
  })"),
                                "three_rooms.json", ".")
      .scene;
}

std::vector<uint32_t> luminaires_of(const DirectReach& reach, uint32_t zone) {
  return reach.zone(zone).luminaires;
}

TEST(DirectReach, EachPointGetsTheLuminairesOfItsRooms) {
  const Scene scene = three_rooms();
  const Plan plan = make_plan(scene);
  ASSERT_TRUE(plan.visibility_test);
  DirectReach reach(scene, plan.visibility_test);
  const std::vector<uint32_t> zone = reach.zones_of(scene.surfaces.at(0));
  using L = std::vector<uint32_t>;
  EXPECT_EQ(luminaires_of(reach, zone[0]), (L{0, 3}));  // in A
  EXPECT_EQ(luminaires_of(reach, zone[1]), (L{1, 3}));  // in B: 3's opening reaches into B
  EXPECT_EQ(luminaires_of(reach, zone[2]), (L{1, 3}));
  EXPECT_EQ(luminaires_of(reach, zone[3]), (L{2}));        // in C
  EXPECT_EQ(luminaires_of(reach, zone[4]), (L{0, 1, 3}));  // on the wall A and B share: both rooms
  EXPECT_EQ(luminaires_of(reach, zone[6]), (L{2}));        // on C's own wall: C only
  // Between B and C, and above them: outside every room, so every luminaire, through the
  // whole scene's tree.
  EXPECT_EQ(zone[7], 0u);
  EXPECT_EQ(zone[8], 0u);
  EXPECT_EQ(luminaires_of(reach, 0), (L{0, 1, 2, 3}));
  EXPECT_EQ(reach.zone(0).visibility, plan.visibility_test);
}

TEST(DirectReach, GivesTheSameIlluminanceAsTestingEveryLuminaire) {
  // The luminaires left out are blocked by a room's boundary, so they add exactly 0 and the
  // sums, added in the same order, are equal to the last bit.
  const Scene scene = three_rooms();
  const Plan plan = make_plan(scene);
  const auto emitters = make_emitters(scene);
  const auto& grid = scene.surfaces.at(0);
  DirectReach reach(scene, plan.visibility_test);
  const GridReach grid_reach{reach, reach.zones_of(grid)};
  DirectCounts every_pair, reachable_pairs;
  const std::vector<double> all = direct_illuminance(plan, emitters, grid, {}, &every_pair);
  const std::vector<double> some =
      direct_illuminance(plan, emitters, grid, {}, &reachable_pairs, &grid_reach);
  ASSERT_EQ(all.size(), some.size());
  for (size_t i = 0; i < all.size(); ++i) EXPECT_EQ(all[i], some[i]) << "point " << i;
  // The checks above test something: B's points see the panel reaching through the wall, the
  // shared wall's point facing A sees A's light, and fewer pairs were computed.
  EXPECT_GT(some[1], 0.0);
  EXPECT_GT(some[5], 0.0);
  EXPECT_GT(some[3], 0.0);
  const auto pairs = [](const DirectCounts& c) {
    return c.far + c.near + c.blended + c.point_sources;
  };
  EXPECT_EQ(pairs(every_pair), 9u * 4u);
  EXPECT_EQ(pairs(reachable_pairs), 2u + 2 + 2 + 1 + 3 + 3 + 1 + 4 + 4);
}

TEST(DirectReach, OneRoomHasOneZone) {
  Scene scene = three_rooms();
  scene.rooms.resize(1);
  DirectReach reach(scene, nullptr);
  const auto zone = reach.zones_of(scene.surfaces.at(0));
  for (const uint32_t z : zone) EXPECT_EQ(z, 0u);
  EXPECT_EQ(reach.zone_count(), 1u);
}

}  // namespace
}  // namespace luxgrid::calc
