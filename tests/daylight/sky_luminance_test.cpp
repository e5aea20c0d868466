// The sky luminance distributions (calc/daylight/sky_luminance.h) against colour-science's
// documented values for the CIE general sky [ISO15469] (docs/daylight.md gives them), and the
// traditional overcast sky's closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "calc/daylight/sky_luminance.h"

namespace luxgrid::daylight {
namespace {

Vec3 from_zenith_azimuth(double zenith_deg, double azimuth_deg) {
  const double z = zenith_deg * kDegToRad, a = azimuth_deg * kDegToRad;
  return {std::sin(z) * std::sin(a), std::sin(z) * std::cos(a), std::cos(z)};
}

// colour-science (colour/phenomena/sky/cie2003.py, its docstrings' examples): phi(0; 4, -0.7) =
// 2.9863412, f(30 deg; 10, -3, 0.45) = 3.3264628. Printed to 7 decimals: 1e-7.
TEST(SkyLuminance, GradationAndIndicatrixPublishedValues) {
  EXPECT_NEAR(gradation(1.0, 4.0, -0.7), 2.9863412, 1e-7);
  EXPECT_NEAR(indicatrix(30.0 * kDegToRad, 10.0, -3.0, 0.45), 3.3264628, 1e-7);
  EXPECT_EQ(gradation(0.0, 4.0, -0.7), 1.0);  // at the horizon
}

// L / L_z at Z = 45 deg, alpha = 180 deg, the sun at Z_s = 30 deg, alpha_s = 0: 0.8325846 for
// type 1, 0.4544524 for type 12 (colour-science).
TEST(SkyLuminance, RelativeLuminancePublishedValues) {
  SkyModel sky;
  sky.kind = SkyKind::cie_general;
  sky.sun = from_zenith_azimuth(30.0, 0.0);
  const Vec3 view = from_zenith_azimuth(45.0, 180.0);
  sky.cie_type = 1;
  EXPECT_NEAR(relative_luminance(sky, view), 0.8325846, 1e-7);
  sky.cie_type = 12;
  EXPECT_NEAR(relative_luminance(sky, view), 0.4544524, 1e-7);
}

TEST(SkyLuminance, ZenithIsOneAndHorizonCuts) {
  for (int type = 1; type <= kCieGeneralSkyTypes; ++type) {
    SkyModel sky;
    sky.kind = SkyKind::cie_general, sky.cie_type = type;
    sky.sun = from_zenith_azimuth(30.0, 180.0);
    EXPECT_NEAR(relative_luminance(sky, Vec3{0, 0, 1}), 1.0, 1e-15) << type;
    EXPECT_EQ(relative_luminance(sky, Vec3{0, 1, 0}), 0.0);
  }
  SkyModel overcast;
  overcast.kind = SkyKind::cie_overcast;
  // (1 + 2 sin h) / 3 at h = 30 deg: 2 / 3.
  EXPECT_NEAR(relative_luminance(overcast, from_zenith_azimuth(60.0, 17.0)), 2.0 / 3.0, 1e-15);
}

TEST(SkyLuminance, NamesAsTheProjectGivesThem) {
  EXPECT_EQ(sky_from_name("cie-overcast")->kind, SkyKind::cie_overcast);
  EXPECT_EQ(sky_from_name("uniform")->kind, SkyKind::uniform);
  EXPECT_EQ(sky_from_name("15")->cie_type, 15);
  EXPECT_EQ(sky_from_name("12")->name(), "12");
  EXPECT_FALSE(sky_from_name("16").has_value());
  EXPECT_FALSE(sky_from_name("0").has_value());
  EXPECT_FALSE(sky_from_name("overcast").has_value());
  EXPECT_THROW(cie_sky_coefficients(16), std::out_of_range);
}

}  // namespace
}  // namespace luxgrid::daylight
