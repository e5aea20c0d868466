// The report's room table figures (report/room_figures.h), worked out before the page: an
// L-shaped room's floor area, perimeter and extent, exact for its axis-aligned outline (1e-12 m
// and m^2 allow for the rounding of the sums).
#include <gtest/gtest.h>

#include "report/room_figures.h"

namespace luxgrid::report {
namespace {

TEST(RoomFigures, AnLShapedRoom) {
  calc::Scene scene;
  calc::Room box;
  box.name = "box";
  box.outline = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  calc::Room l_room;
  l_room.name = "L";
  // 4 x 2 plus 2 x 1 on top of its left half: 10 m^2, edges 4 + 2 + 2 + 1 + 2 + 3 = 14 m.
  l_room.outline = {{1, 1}, {5, 1}, {5, 3}, {3, 3}, {3, 4}, {1, 4}};
  scene.rooms = {box, l_room};
  const std::vector<RoomFigures> f = room_figures(scene);
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f[0].room, "box");
  EXPECT_NEAR(f[0].floor_area_m2, 2.0, 1e-12);
  EXPECT_NEAR(f[0].perimeter_m, 6.0, 1e-12);
  EXPECT_EQ(f[1].room, "L");
  EXPECT_NEAR(f[1].floor_area_m2, 10.0, 1e-12);
  EXPECT_NEAR(f[1].perimeter_m, 14.0, 1e-12);
  EXPECT_NEAR(f[1].size_x_m, 4.0, 1e-12);
  EXPECT_NEAR(f[1].size_y_m, 3.0, 1e-12);
}

}  // namespace
}  // namespace luxgrid::report
