// The table rung's trig-free ray angle (calc/nearfield/ray_angle.h) against the library's atan2,
// from the sine and cosine the rung computes (cos = 1 / sqrt(1 + x^2), sin = x cos for a ray's
// tan(gamma') = x): at every bin edge and either side of it, across the bins, near 0, around 45
// degrees and towards 90.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "calc/nearfield/ray_angle.h"

namespace luxgrid::nearfield {
namespace {

// A few units in the last place of the angle, relative (so also for tiny angles).
void expect_close_to_atan2(double x) {
  const double c = 1.0 / std::sqrt(1.0 + x * x), s = x * c;
  const double want = std::atan2(s, c), got = ray_angle(s, c);
  EXPECT_LE(std::abs(got - want), 4.0 * std::numeric_limits<double>::epsilon() * want)
      << "x = " << x;
}

TEST(RayAngle, AgreesWithAtan2ToAFewUnitsInTheLastPlace) {
  EXPECT_EQ(ray_angle(0.0, 1.0), 0.0);
  EXPECT_NEAR(ray_angle(1.0, 0.0), 0.5 * kPi, 1e-16);
  std::vector<double> xs = {1e-300, 1e-12, 1e-6, 1e-3, 0.1, 0.5, 1.0, 2.0, 10.0, 1e3, 1e6, 1e12};
  for (int j = 1; j < kRayAngleBins; ++j) {
    // tan of the bin edge, and of the mirrored edge beyond 45 degrees.
    const double u = j / (kRayAngleBins * std::sqrt(2.0)), t = u / std::sqrt(1.0 - u * u);
    for (double x : {t, 1.0 / t})
      xs.insert(xs.end(), {x, std::nextafter(x, 0.0), std::nextafter(x, 1e308), x * (1 + 1e-9)});
  }
  xs.insert(xs.end(), {std::nextafter(1.0, 0.0), std::nextafter(1.0, 2.0)});
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> angle(0.0, 0.5 * kPi);
  for (int i = 0; i < 100000; ++i) xs.push_back(std::tan(angle(rng)));
  for (double x : xs) expect_close_to_atan2(x);
}

TEST(RayAngle, DirectionAngleAgreesWithAtan2InEveryQuadrant) {
  std::mt19937_64 rng(18);
  std::uniform_real_distribution<double> angle(-kPi, kPi), log_r(-8.0, 3.0);
  for (int i = 0; i < 100000; ++i) {
    const double a = angle(rng), r = std::pow(10.0, log_r(rng));
    const double x = r * std::cos(a), y = r * std::sin(a);
    const double want = std::atan2(y, x);
    EXPECT_LE(std::abs(direction_angle(y, x) - want),
              4.0 * std::numeric_limits<double>::epsilon() * std::abs(want))
        << x << " " << y;
  }
  // The axes and the diagonals exactly where atan2 is exact.
  EXPECT_EQ(direction_angle(0.0, 1.0), 0.0);
  EXPECT_EQ(direction_angle(0.0, 0.0), 0.0);
  EXPECT_NEAR(direction_angle(1.0, 0.0), 0.5 * kPi, 1e-16);
  EXPECT_NEAR(direction_angle(0.0, -1.0), kPi, 1e-16);
  EXPECT_NEAR(direction_angle(-1.0, 0.0), -0.5 * kPi, 1e-16);
  EXPECT_NEAR(direction_angle(-2.0, -2.0), -0.75 * kPi, 2e-16);
}

}  // namespace
}  // namespace luxgrid::nearfield
