#include "calc/daylight/clear_glass.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace luxgrid::daylight {
namespace {

constexpr double kN = kGlassRefractiveIndex;

// A pane's transmittance for one polarisation with surface reflectance r and one-pass internal
// transmissivity t: the series (1 - r)^2 t sum (r t)^2k = (1 - r)^2 t / (1 - r^2 t^2).
double pane(double r, double t) { return (1.0 - r) * (1.0 - r) * t / (1.0 - r * r * t * t); }

double normal_reflectance() { return ((kN - 1.0) / (kN + 1.0)) * ((kN - 1.0) / (kN + 1.0)); }

}  // namespace

double lossless_normal_transmittance() {
  const double r = normal_reflectance();
  return (1.0 - r) / (1.0 + r);
}

ClearGlass::ClearGlass(double normal_transmittance) : normal_transmittance_(normal_transmittance) {
  if (!(normal_transmittance > 0.0 && normal_transmittance <= lossless_normal_transmittance()))
    throw std::invalid_argument("normal transmittance outside (0, 0.9183]");
  // T = (1 - r)^2 t / (1 - r^2 t^2) solved for t: T r^2 t^2 + (1 - r)^2 t - T = 0, the positive
  // root (Radiance's tn formula for n = 1.52 is this root with its constants evaluated), written
  // as 2 T / (q + sqrt(q^2 + 4 T^2 r^2)) so that nothing cancels.
  const double r = normal_reflectance(), T = normal_transmittance;
  const double q = (1.0 - r) * (1.0 - r);
  transmissivity_ = 2.0 * T / (q + std::sqrt(q * q + 4.0 * T * T * r * r));
  transmissivity_ = std::min(transmissivity_, 1.0);
}

double ClearGlass::transmittance(double cos_incidence) const {
  const double cos_i = std::min(std::abs(cos_incidence), 1.0);
  if (!(cos_i > 0.0)) return 0.0;
  // Snell: cos of the refracted angle.
  const double cos_t = std::sqrt(1.0 - (1.0 - cos_i * cos_i) / (kN * kN));
  const double rs = (cos_i - kN * cos_t) / (cos_i + kN * cos_t);  // perpendicular (TE)
  const double rp = (cos_t - kN * cos_i) / (cos_t + kN * cos_i);  // parallel (TM)
  const double t = std::pow(transmissivity_, 1.0 / cos_t);        // path length 1 / cos_t
  return 0.5 * (pane(rs * rs, t) + pane(rp * rp, t));
}

}  // namespace luxgrid::daylight
