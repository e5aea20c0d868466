#pragma once
// What the report's room table shows of each room beyond the project's own values, worked out
// before the page (report/html_report.h only presents): the floor area, the perimeter and the
// outline's extent along x and y.
#include <string>
#include <vector>

#include "calc/scene.h"

namespace luxgrid::report {

struct RoomFigures {
  std::string room;
  double floor_area_m2 = 0.0;
  double perimeter_m = 0.0;
  double size_x_m = 0.0, size_y_m = 0.0;  // the outline's bounding box
};

// One per room of the scene, in its order.
std::vector<RoomFigures> room_figures(const calc::Scene& scene);

}  // namespace luxgrid::report
