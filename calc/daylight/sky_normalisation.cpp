#include "calc/daylight/sky_normalisation.h"

#include <cmath>

namespace luxgrid::daylight {

QuadratureResult horizontal_illuminance_per_zenith_luminance(const SkyModel& sky,
                                                             double relative_tolerance) {
  // Azimuth alpha clockwise from +y, as the scene's azimuths are (docs/daylight.md).
  const double sun_azimuth_rad = std::atan2(sky.sun.x, sky.sun.y);
  const double sun_zenith_rad = angle_between(Vec3{0, 0, 1}, sky.sun);
  const double inner_tolerance = 0.1 * relative_tolerance;
  double inner_error = 0.0;
  int evaluations = 0;
  const auto over_zenith = [&](double alpha) {
    const double sin_a = std::sin(alpha), cos_a = std::cos(alpha);
    const auto integrand = [&](double zenith) {
      const double s = std::sin(zenith), c = std::cos(zenith);
      return relative_luminance(sky, Vec3{s * sin_a, s * cos_a, c}) * c * s;
    };
    const QuadratureResult r =
        integrate_adaptive(integrand, 0.0, kPi / 2.0, inner_tolerance, 0.0, {sun_zenith_rad});
    inner_error += r.error_estimate, evaluations += r.evaluations;
    return r.value;
  };
  QuadratureResult outer =
      integrate_adaptive(over_zenith, sun_azimuth_rad - kPi, sun_azimuth_rad + kPi,
                         relative_tolerance, 0.0, {sun_azimuth_rad});
  // Each inner estimate bounds one node's error; the weights of QK15 sum to the interval, so
  // their mean over 2 pi bounds what they add to the outer integral.
  outer.error_estimate += inner_error / std::max(1, outer.evaluations) * kTwoPi;
  outer.evaluations = evaluations;
  return outer;
}

}  // namespace luxgrid::daylight
