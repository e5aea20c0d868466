#include "report/luminaire_outline.h"

#include <cmath>

namespace luxgrid::report {

std::vector<Vec3> luminous_outline(const calc::Luminaire& l) {
  using Shape = photometry::LuminousOpening::Shape;
  const auto& o = l.opening;
  std::vector<Vec3> local;
  if (o.shape == Shape::rectangle && o.length > 0 && o.width > 0) {
    const double a = o.length / 2, b = o.width / 2;
    local = {{-a, -b, 0}, {a, -b, 0}, {a, b, 0}, {-a, b, 0}};
  } else if (o.shape == Shape::disk && o.length > 0) {
    constexpr int kSides = 32;
    const double a = o.length / 2, b = (o.width > 0 ? o.width : o.length) / 2;
    for (int k = 0; k < kSides; ++k) {
      const double t = 2 * kPi * k / kSides;
      local.push_back({a * std::cos(t), b * std::sin(t), 0});
    }
  }
  std::vector<Vec3> world;
  for (const Vec3& p : local) world.push_back(l.pose.position + l.pose.rotation * p);
  return world;
}

}  // namespace luxgrid::report
