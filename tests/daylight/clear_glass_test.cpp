// Radiance's clear glass (calc/daylight/clear_glass.h): T_n back at normal incidence, 0 at
// grazing, and at other angles against an independent evaluation: Fresnel's coefficients in
// their sine and tangent forms and the series of internal reflections summed term by term,
// with the internal transmissivity from Radiance's own closed form for n = 1.52.
#include <gtest/gtest.h>

#include <cmath>

#include "calc/daylight/clear_glass.h"
#include "util/robust_math.h"

namespace luxgrid::daylight {
namespace {

// Radiance's glass documentation (ray/doc: "tn = (sqrt(.8402528435+.0072522239*Tn*Tn)
// -.9166530661)/.0036261119/Tn"): the transmissivity for n = 1.52.
double radiance_transmissivity(double Tn) {
  return (std::sqrt(0.8402528435 + 0.0072522239 * Tn * Tn) - 0.9166530661) / 0.0036261119 / Tn;
}

double independent_transmittance(double Tn, double incidence_deg) {
  const double n = 1.52, ti = incidence_deg * kDegToRad;
  const double tt = std::asin(std::sin(ti) / n);
  const double rs = std::pow(std::sin(ti - tt) / std::sin(ti + tt), 2);
  const double rp = std::pow(std::tan(ti - tt) / std::tan(ti + tt), 2);
  const double pass = std::pow(radiance_transmissivity(Tn), 1.0 / std::cos(tt));
  double total = 0.0;
  for (double r : {rs, rp}) {
    double series = 0.0, term = (1 - r) * (1 - r) * pass;
    for (int k = 0; k < 200; ++k, term *= r * r * pass * pass) series += term;
    total += 0.5 * series;
  }
  return total;
}

TEST(ClearGlass, NormalIncidenceGivesTnBack) {
  for (double Tn : {0.88, 0.5, 0.1, 0.91}) {
    const ClearGlass glass(Tn);
    EXPECT_NEAR(glass.transmittance(1.0), Tn, 1e-15) << Tn;
    EXPECT_NEAR(glass.transmittance(-1.0), Tn, 1e-15) << Tn;
  }
}

TEST(ClearGlass, GrazingGivesZero) {
  EXPECT_EQ(ClearGlass(0.88).transmittance(0.0), 0.0);
  EXPECT_LT(ClearGlass(0.88).transmittance(1e-6), 1e-5);
}

// Radiance's constants are printed to 10 digits and its formula subtracts two numbers near 0.92
// before dividing by 0.0036 Tn: good to about 1e-9 / (0.0036 Tn), so 2e-6 for Tn >= 0.2.
TEST(ClearGlass, TransmissivityAsRadiance) {
  for (double Tn : {0.88, 0.6, 0.2})
    EXPECT_NEAR(ClearGlass(Tn).normal_transmissivity(), radiance_transmissivity(Tn), 2e-6) << Tn;
}

TEST(ClearGlass, AnglesAgainstIndependentEvaluation) {
  for (double Tn : {0.88, 0.6})
    for (double deg : {10.0, 30.0, 45.0, 60.0, 75.0, 85.0, 89.0}) {
      const double value = ClearGlass(Tn).transmittance(std::cos(deg * kDegToRad));
      // The independent evaluation carries Radiance's transmissivity (2e-6, above).
      EXPECT_NEAR(value, independent_transmittance(Tn, deg), 2e-6) << Tn << " at " << deg;
    }
  // Falls with the angle: at 60 degrees a 0.88 pane lets through less than at 30.
  const ClearGlass glass(0.88);
  EXPECT_LT(glass.transmittance(std::cos(60 * kDegToRad)),
            glass.transmittance(std::cos(30 * kDegToRad)));
}

TEST(ClearGlass, RefusesImpossibleTransmittance) {
  EXPECT_THROW(ClearGlass(0.0), std::invalid_argument);
  EXPECT_THROW(ClearGlass(0.95), std::invalid_argument);  // above the lossless 0.9183
  // r = (0.52 / 2.52)^2 = 0.0425800; (1 - r) / (1 + r) = 0.9183180.
  EXPECT_NEAR(lossless_normal_transmittance(), 0.9183180, 1e-7);
}

}  // namespace
}  // namespace luxgrid::daylight
