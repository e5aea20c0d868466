// Each sky's horizontal illuminance per unit zenith luminance (calc/daylight/sky_normalisation.h):
// the uniform sky pi and the traditional overcast 7 pi / 9 in closed form; the general skies
// against an independent brute-force midpoint rule on a fine grid of the hemisphere, for a sun
// high and low.
#include <gtest/gtest.h>

#include <cmath>

#include "calc/daylight/sky_normalisation.h"

namespace luxgrid::daylight {
namespace {

Vec3 sun_at_zenith_azimuth(double zenith_deg, double azimuth_deg) {
  const double z = zenith_deg * kDegToRad, a = azimuth_deg * kDegToRad;
  return {std::sin(z) * std::sin(a), std::sin(z) * std::cos(a), std::cos(z)};
}

TEST(SkyNormalisation, UniformAndOvercastClosedForms) {
  SkyModel uniform;
  EXPECT_NEAR(horizontal_illuminance_per_zenith_luminance(uniform).value, kPi, 1e-12);
  SkyModel overcast;
  overcast.kind = SkyKind::cie_overcast;
  EXPECT_NEAR(horizontal_illuminance_per_zenith_luminance(overcast).value, 7.0 * kPi / 9.0, 1e-12);
}

// The midpoint rule over (cos^2 Z, alpha): with u = cos^2 Z, cos Z sin Z dZ = du / 2, so the
// integrand is L / L_z alone; 300 x 600 cells. Its own error (the indicatrix's cusp at the sun)
// reaches 7e-5 relative (types 14 and 15 with the sun low), falling as the square of the cell
// size (a quarter of that with the cells halved, which takes the test 2 s): tolerance 1e-4.
double midpoint_rule(const SkyModel& sky) {
  constexpr int kU = 300, kAlpha = 600;
  double sum = 0.0;
  for (int i = 0; i < kU; ++i) {
    const double u = (i + 0.5) / kU, cos_z = std::sqrt(u), sin_z = std::sqrt(1.0 - u);
    for (int j = 0; j < kAlpha; ++j) {
      const double alpha = (j + 0.5) * kTwoPi / kAlpha;
      sum += relative_luminance(sky, Vec3{sin_z * std::sin(alpha), sin_z * std::cos(alpha), cos_z});
    }
  }
  return sum * 0.5 / kU * kTwoPi / kAlpha;
}

TEST(SkyNormalisation, GeneralSkiesAgainstBruteForce) {
  for (double sun_zenith_deg : {30.0, 75.0}) {
    for (int type = 1; type <= kCieGeneralSkyTypes; ++type) {
      SkyModel sky;
      sky.kind = SkyKind::cie_general, sky.cie_type = type;
      sky.sun = sun_at_zenith_azimuth(sun_zenith_deg, 160.0);
      const QuadratureResult r = horizontal_illuminance_per_zenith_luminance(sky);
      EXPECT_NEAR(r.value, midpoint_rule(sky), 1e-4 * r.value)
          << "type " << type << ", sun zenith " << sun_zenith_deg;
      EXPECT_LE(r.error_estimate, 1e-8 * r.value) << type;
    }
  }
}

// Type 5 has a = c = e = 0: uniform, pi whatever the sun.
TEST(SkyNormalisation, TypeFiveIsUniform) {
  SkyModel sky;
  sky.kind = SkyKind::cie_general, sky.cie_type = 5;
  sky.sun = sun_at_zenith_azimuth(30.0, 180.0);
  EXPECT_NEAR(horizontal_illuminance_per_zenith_luminance(sky).value, kPi, 1e-12);
}

}  // namespace
}  // namespace luxgrid::daylight
