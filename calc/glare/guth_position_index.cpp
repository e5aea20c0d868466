#include "calc/glare/guth_position_index.h"

#include <cmath>

#include "util/robust_math.h"

namespace luxgrid::calc::glare {

bool in_guth_field(double R_m, double T_m, double H_m) {
  if (!(R_m > 0.0) || !(H_m >= 0.0)) return false;
  return H_m <= kGuthMaxHOverR * R_m && std::abs(T_m) <= kGuthMaxTOverR * R_m;
}

double guth_position_index(double H_over_R, double T_over_R) {
  const double h = std::abs(H_over_R), t = std::abs(T_over_R);
  const double sigma = std::atan(std::hypot(h, t)) * kRadToDeg;
  // On the line of sight tau is undefined and sigma = 0, where p = 1 whatever tau is.
  const double tau = (h == 0.0 && t == 0.0) ? 0.0 : std::atan2(t, h) * kRadToDeg;
  const double a = (35.2 - 0.31889 * tau - 1.22 * std::exp(-2.0 * tau / 9.0)) * 1e-3;
  const double b = (21.0 + 0.26667 * tau - 0.002963 * tau * tau) * 1e-5;
  return std::exp(sigma * (a + b * sigma));
}

}  // namespace luxgrid::calc::glare
