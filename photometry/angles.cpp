#include <cmath>

#include "photometry/intensity_distribution.h"

namespace luxgrid::photometry {

Vec3 direction_of(double c, double gamma) {
  const double s = std::sin(gamma);
  return {s * std::cos(c), s * std::sin(c), -std::cos(gamma)};
}

}  // namespace luxgrid::photometry
