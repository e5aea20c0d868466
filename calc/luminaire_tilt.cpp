#include "calc/luminaire_tilt.h"

#include <cmath>

#include "calc/scaled_distribution.h"

namespace luxgrid::calc {

double lamp_tilt_deg(const glm::dmat3& rotation, int geometry) {
  const Vec3 up(0.0, 0.0, 1.0);
  if (geometry == 2 || geometry == 3) {
    const Vec3 lamp_axis = rotation * (geometry == 2 ? Vec3(1, 0, 0) : Vec3(0, 1, 0));
    return safe_asin(std::abs(glm::dot(lamp_axis, up))) * kRadToDeg;
  }
  return angle_between(rotation * up, up) * kRadToDeg;
}

void apply_tilt_factors(Scene& scene) {
  for (auto& lum : scene.luminaires) {
    const auto it = scene.photometry.find(lum.photometry);
    if (it == scene.photometry.end() || !it->second.tilt) continue;
    const auto& table = *it->second.tilt;
    const double factor =
        table.factor_at(lamp_tilt_deg(lum.pose.rotation, table.lamp_to_luminaire_geometry));
    if (factor != 1.0)
      lum.distribution = std::make_shared<ScaledDistribution>(lum.distribution, factor);
  }
}

}  // namespace luxgrid::calc
