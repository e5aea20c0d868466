#include "photometry/tilt.h"

#include <algorithm>
#include <cmath>

namespace luxgrid::photometry {

double TiltTable::factor_at(double tilt_deg) const {
  if (angle_deg.empty()) return 1.0;
  const double a = std::abs(tilt_deg);
  if (a <= angle_deg.front()) return factor.front();
  if (a >= angle_deg.back()) return factor.back();
  const auto it = std::upper_bound(angle_deg.begin(), angle_deg.end(), a);
  const std::size_t k = static_cast<std::size_t>(it - angle_deg.begin());
  const double t = (a - angle_deg[k - 1]) / (angle_deg[k] - angle_deg[k - 1]);
  return factor[k - 1] + t * (factor[k] - factor[k - 1]);
}

}  // namespace luxgrid::photometry
