// Grid points in an opening are left out (calc/points_in_openings.h): counted per grid, kept in
// the nu x nv layout with active = false, a point on the opening's edge kept, a grid beside the
// face's plane untouched, and a grid with nothing left warned about.
#include <gtest/gtest.h>

#include "project_error.h"

namespace luxgrid::project {
namespace {

// A 4 x 4 x 3 m room whose south wall (y = 0) has a window; the wall's grid at 0.5 m has cell
// centres at 0.25, 0.75, ... along x (from the wall's first corner) and up z.
nlohmann::json windowed_room(const std::string& window) {
  return nlohmann::json::parse(R"({
    "format": "luxgrid-project/1",
    "rooms": [{"name": "r", "outline": [[0,0],[4,0],[4,4],[0,4]], "height": 3}],
    "openings": [{"name": "w", "room": "r", "polygon": )" +
                               window + R"(}],
    "daylight": {"sky": {"type": "cie-overcast"}},
    "surfaces": [
      {"name": "room", "room_surfaces": {"room": "r"}, "spacing": 0.5},
      {"name": "inside", "plane": {"origin": [0, 0.01, 0], "u": [1, 0, 0], "v": [0, 0, 1],
                                   "size": [4, 3]}, "spacing": 0.5},
      {"name": "probe", "points": [{"at": [2, 0, 1.5], "normal": [0, 1, 0]}]}
    ]
  })");
}

const geometry::SurfaceGrid& grid_named(const Scene& s, const std::string& name) {
  for (const auto& g : s.surfaces)
    if (g.name == name) return g;
  throw std::runtime_error("no grid " + name);
}

std::size_t inactive_count(const geometry::SurfaceGrid& g) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < g.points.size(); ++i) n += !g.active.empty() && !g.active[i];
  return n;
}

TEST(PointsInOpenings, TheWindowsPointsAreLeftOutAndItsEdgesKept) {
  // x in [1.25, 2.75], z in [0.75, 1.75]: the centres 1.25 and 2.75 (x) and 0.75 and 1.75 (z) lie
  // on its edges and stay; strictly inside are x = 1.75, 2.25 at z = 1.25: two points.
  const Scene s =
      parse_project(windowed_room("[[1.25,0,0.75],[2.75,0,0.75],[2.75,0,1.75],[1.25,0,1.75]]"),
                    "p.json", ".")
          .scene;
  const auto& wall = grid_named(s, "room wall 0");
  EXPECT_EQ(wall.points_in_openings, 2u);
  EXPECT_EQ(inactive_count(wall), 2u);
  for (std::size_t i = 0; i < wall.points.size(); ++i) {
    const Vec3& p = wall.points[i];
    const bool in =
        p.x > 1.25 + 1e-9 && p.x < 2.75 - 1e-9 && p.z > 0.75 + 1e-9 && p.z < 1.75 - 1e-9;
    EXPECT_EQ(wall.active[i], !in) << p.x << " " << p.z;
  }
  // The other walls, the floor and ceiling, a plane 1 cm inside the wall and a named point in the
  // window keep every point.
  for (const auto& g : s.surfaces) {
    if (g.name == "room wall 0") continue;
    EXPECT_EQ(g.points_in_openings, 0u) << g.name;
    EXPECT_EQ(inactive_count(g), 0u) << g.name;
  }
  EXPECT_TRUE(s.warnings.empty());
}

TEST(PointsInOpenings, AWallThatIsAllOpeningIsWarnedAbout) {
  // CIE 171's facade opening fills the whole wall: its grid has nothing left.
  const Scene s =
      parse_project(windowed_room("[[0,0,0],[4,0,0],[4,0,3],[0,0,3]]"), "p.json", ".").scene;
  const auto& wall = grid_named(s, "room wall 0");
  EXPECT_EQ(wall.points_in_openings, wall.points.size());
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_EQ(s.warnings[0].text(),
            "p.json /surfaces/0: surface \"room wall 0\": every point lies in an opening (no "
            "surface there): no results");
}

}  // namespace
}  // namespace luxgrid::project
