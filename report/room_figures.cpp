#include "report/room_figures.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/polygon.h"

namespace luxgrid::report {

std::vector<RoomFigures> room_figures(const calc::Scene& scene) {
  std::vector<RoomFigures> out;
  for (const auto& room : scene.rooms) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    double x0 = kInf, y0 = kInf, x1 = -kInf, y1 = -kInf;
    for (const Vec2& v : room.outline) {
      x0 = std::min(x0, v.x), x1 = std::max(x1, v.x);
      y0 = std::min(y0, v.y), y1 = std::max(y1, v.y);
    }
    out.push_back({room.name, std::abs(geometry::signed_area(room.outline)),
                   geometry::perimeter(room.outline), x1 - x0, y1 - y0});
  }
  return out;
}

}  // namespace luxgrid::report
