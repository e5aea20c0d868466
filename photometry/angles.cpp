#include <cmath>

#include "photometry/intensity_distribution.h"

namespace luxgrid::photometry {

PhotometricAngles angles_of(const Vec3& d) {
  const double horizontal = std::hypot(d.x, d.y);
  const double gamma = std::atan2(horizontal, -d.z);  // 0 at nadir, pi at zenith
  double c = std::atan2(d.y, d.x);
  if (c < 0.0) c += 2.0 * kPi;
  if (c >= 2.0 * kPi) c = 0.0;
  return {c, gamma};
}

Vec3 direction_of(double c, double gamma) {
  const double s = std::sin(gamma);
  return {s * std::cos(c), s * std::sin(c), -std::cos(gamma)};
}

}  // namespace luxgrid::photometry
