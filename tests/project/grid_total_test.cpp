// A project refused for the points of all its surfaces together is refused before any surface is
// built: every surface is charged its points from its definition first (project/project_parts.h,
// GridBudget), so the refusal costs no grid memory (it once built up to 8 million points first).
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "project_error.h"

namespace luxgrid::project {
namespace {

// A 10 x 10 m room filled by one obstacle, so its workplane's grid, once built, has no point
// outside the obstacle: a refusal the loader can only make after building that grid.
nlohmann::json filled_room_project() {
  return nlohmann::json::parse(R"({
    "format": "luxgrid-project/1",
    "photometry": { "iso": { "builtin": "isotropic", "intensity_cd": 100 } },
    "rooms": [ { "name": "r", "outline": [[0,0],[10,0],[10,10],[0,10]], "height": 3,
                 "obstacles": [ { "name": "block", "box": { "min": [0, 0, 0], "max": [10, 10, 3] } } ] } ],
    "luminaires": [ { "photometry": "iso", "position": [5, 5, 2.9] } ],
    "surfaces": [ { "name": "wp", "workplane": { "room": "r", "height": 0.8 }, "spacing": 1 } ]
  })");
}

// A 2000 x 2000 m plane at 1 m: 4 million points, the most one grid may have.
nlohmann::json largest_plane(const std::string& name) {
  return {{"name", name},
          {"plane",
           {{"origin", {0, 0, 0}}, {"u", {1, 0, 0}}, {"v", {0, 1, 0}}, {"size", {2000, 2000}}}},
          {"spacing", 1}};
}

TEST(GridTotal, TheFilledRoomsWorkplaneIsRefusedOnceBuilt) {
  // The premise of the next test: building surface 0 is refused.
  EXPECT_EQ(error_of(filled_room_project()),
            "p.json /surfaces/0: no grid point lies inside the workplane and outside obstacles; "
            "use a smaller spacing");
}

TEST(GridTotal, RefusedForTheTotalBeforeAnySurfaceIsBuilt) {
  // Surface 0 (100 points) then two of the largest grids: 8 000 100 points in all, over the limit
  // of 8 000 000 at surface 2. Had surface 0 been built first, its own refusal would come first.
  nlohmann::json doc = filled_room_project();
  doc["surfaces"].push_back(largest_plane("a"));
  doc["surfaces"].push_back(largest_plane("b"));
  EXPECT_EQ(error_of(doc),
            "p.json /surfaces/2: the surfaces would have 8000100 points together, more than the "
            "limit of 8000000; use larger spacings or fewer surfaces");
}

}  // namespace
}  // namespace luxgrid::project
