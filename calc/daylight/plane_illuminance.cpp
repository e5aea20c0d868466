#include "calc/daylight/plane_illuminance.h"

#include <cmath>

#include "calc/daylight/gauss_kronrod.h"

namespace luxgrid::daylight {

double plane_illuminance_lx(const SkyModel& sky, double sky_lx_per_relative, double ground_lx,
                            const Vec3& outward_normal,
                            const std::function<double(double)>& weight) {
  // Directions d at angle theta from the normal and phi about it, phi from e1 (horizontal)
  // towards e2 (up the plane, where it has an up).
  const Vec3 out = outward_normal;
  Vec3 e2 = Vec3{0, 0, 1} - out.z * out;
  e2 = glm::length(e2) > 1e-12 ? glm::normalize(e2) : Vec3{0, 1, 0};
  const Vec3 e1 = glm::cross(e2, out);
  const auto over_theta = [&](double phi) {
    const Vec3 across = std::cos(phi) * e1 + std::sin(phi) * e2;
    const auto integrand = [&](double theta) {
      const double c = std::cos(theta), sn = std::sin(theta);
      const Vec3 d = c * out + sn * across;
      const double luminance =
          d.z > 0.0 ? sky_lx_per_relative * relative_luminance(sky, d) : ground_lx;
      return luminance * weight(c) * c * sn;
    };
    return integrate_adaptive(integrand, 0.0, kPi / 2.0, 1e-8, 0.0).value;
  };
  return integrate_adaptive(over_theta, 0.0, kTwoPi, 1e-7, 0.0, {kPi}).value;
}

}  // namespace luxgrid::daylight
