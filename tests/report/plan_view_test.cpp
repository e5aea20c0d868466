// The plan view draws what the room holds where it stands: obstacles at their footprint.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "geometry/room.h"
#include "report/plan_view_svg.h"

namespace luxgrid::report {
namespace {

// The numbers of the `points` attribute of the first <polygon class="obstacle" ...>.
std::vector<double> obstacle_points(const std::string& svg) {
  std::smatch m;
  const std::regex re("<polygon class=\"obstacle\" points=\"([^\"]*)\"");
  if (!std::regex_search(svg, m, re)) return {};
  std::vector<double> out;
  const std::string pts = m[1];
  const std::regex num("-?[0-9.]+");
  for (auto it = std::sregex_iterator(pts.begin(), pts.end(), num); it != std::sregex_iterator();
       ++it)
    out.push_back(std::stod(it->str()));
  return out;
}

TEST(PlanView, ObstacleFootprintIsDrawnWhereItStands) {
  calc::Room room;
  room.name = "r";
  room.outline = {{0, 0}, {10, 0}, {10, 5}, {0, 5}};
  room.height = 3.0;
  room.obstacles.push_back(geometry::make_box("column", {4, 1, 0}, {5, 2, 3}, 0.0, 0.5));
  const std::string svg = plan_view_svg(room, {}, {}, 640);
  const auto p = obstacle_points(svg);
  ASSERT_EQ(p.size(), 8u) << "a box footprint has four corners";
  // 640 px wide, 40 px padding each side: 56 px per metre; x = 40 + 56 x, y = 40 + 56 (5 - y).
  // The coordinates are printed with one decimal, so 0.05 px is the rounding bound.
  double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
  for (size_t i = 0; i < p.size(); i += 2) {
    xmin = std::min(xmin, p[i]);
    xmax = std::max(xmax, p[i]);
    ymin = std::min(ymin, p[i + 1]);
    ymax = std::max(ymax, p[i + 1]);
  }
  EXPECT_NEAR(xmin, 40 + 56 * 4, 0.05);
  EXPECT_NEAR(xmax, 40 + 56 * 5, 0.05);
  EXPECT_NEAR(ymin, 40 + 56 * 3, 0.05);
  EXPECT_NEAR(ymax, 40 + 56 * 4, 0.05);
  EXPECT_NE(svg.find("obstacle column"), std::string::npos) << "the tooltip names it";
}

TEST(PlanView, NoObstacleNoObstacleShape) {
  calc::Room room;
  room.name = "r";
  room.outline = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  room.height = 3.0;
  EXPECT_TRUE(obstacle_points(plan_view_svg(room, {}, {}, 640)).empty());
}

// The north arrow points to true north: up (+y) by default, turned clockwise about its middle by
// a daylight site's north angle (SVG's y runs down, so a positive rotate() is clockwise).
TEST(PlanView, NorthArrowTurnsByTheNorthAngle) {
  calc::Room room;
  room.name = "r";
  room.outline = {{0, 0}, {10, 0}, {10, 5}, {0, 5}};
  room.height = 3.0;
  const std::string up = plan_view_svg(room, {}, {}, 640);
  EXPECT_NE(up.find("<g class=\"north\"><polygon"), std::string::npos);
  const std::string turned = plan_view_svg(room, {}, {}, 640, {}, 30.0);
  // The arrow's tip is at (620, 10), its middle 15 px below.
  EXPECT_NE(turned.find("<g class=\"north\" transform=\"rotate(30.0 620.0 25.0)\"><polygon"),
            std::string::npos)
      << turned;
}

}  // namespace
}  // namespace luxgrid::report
