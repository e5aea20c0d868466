// The table angles (util/table_angle.h) against the library's atan2: the table itself; the
// quadrant angle from the sine and cosine the near field's table rung computes (cos =
// 1 / sqrt(1 + x^2), sin = x cos for a ray's tan(gamma') = x); the arc angle of Lambert's formula
// from |a x b| and a . b of unit vectors over the whole half turn; the direction angle in every
// quadrant. At every bin edge and either side of it, near 0, 45, 90, 135 and 180 degrees, for
// denormal sines, and for the pairs the arc angle hands to atan2.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "util/table_angle.h"

namespace luxgrid {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Within `ulps` units in the last place of atan2's result (relative, so also for tiny angles).
void expect_within_ulps(double got, double want, double ulps, const char* what, double a,
                        double b) {
  EXPECT_LE(std::abs(got - want), ulps * kEps * std::abs(want))
      << what << "(" << a << ", " << b << ") = " << got << ", atan2 " << want;
}

TEST(TableAngle, TableIsWhatItsFormulaGives) {
  for (int j = 0; j < kAngleTableBins; ++j) {
    const AngleTableRow& row = kAngleTable[j];
    const double s = j / (kAngleTableBins * std::sqrt(2.0));
    // sqrt and the division are correctly rounded everywhere; a library's atan2 may differ from
    // the one the table was written with in the last place.
    EXPECT_EQ(row.sin, s) << j;
    EXPECT_EQ(row.cos, std::sqrt(1.0 - s * s)) << j;
    EXPECT_LE(std::abs(row.angle - std::atan2(row.sin, row.cos)), kEps * row.angle) << j;
  }
}

void expect_quadrant_close_to_atan2(double x) {
  const double c = 1.0 / std::sqrt(1.0 + x * x), s = x * c;
  expect_within_ulps(quadrant_angle(s, c), std::atan2(s, c), 4.0, "quadrant_angle", s, c);
}

TEST(TableAngle, QuadrantAngleAgreesWithAtan2ToAFewUnitsInTheLastPlace) {
  EXPECT_EQ(quadrant_angle(0.0, 1.0), 0.0);
  EXPECT_NEAR(quadrant_angle(1.0, 0.0), 0.5 * kPi, 1e-16);
  std::vector<double> xs = {1e-300, 1e-12, 1e-6, 1e-3, 0.1, 0.5, 1.0, 2.0, 10.0, 1e3, 1e6, 1e12};
  for (int j = 1; j < kAngleTableBins; ++j) {
    // tan of the bin edge, and of the mirrored edge beyond 45 degrees.
    const double u = j / (kAngleTableBins * std::sqrt(2.0)), t = u / std::sqrt(1.0 - u * u);
    for (double x : {t, 1.0 / t})
      xs.insert(xs.end(), {x, std::nextafter(x, 0.0), std::nextafter(x, 1e308), x * (1 + 1e-9)});
  }
  xs.insert(xs.end(), {std::nextafter(1.0, 0.0), std::nextafter(1.0, 2.0)});
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> angle(0.0, 0.5 * kPi);
  for (int i = 0; i < 100000; ++i) xs.push_back(std::tan(angle(rng)));
  for (double x : xs) expect_quadrant_close_to_atan2(x);
}

// |a x b| and a . b of unit vectors a and b (each normalised in double, as Lambert's formula
// does) at the arc `theta` from each other, in a random plane.
struct SinCos {
  double s, c;
};
SinCos unit_pair_at(double theta, std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  const Vec3 a = glm::normalize(Vec3(g(rng), g(rng), g(rng)));
  const Vec3 p = glm::normalize(glm::cross(a, Vec3(g(rng), g(rng), g(rng))));
  const Vec3 b = glm::normalize(a * std::cos(theta) + p * std::sin(theta));
  return {glm::length(glm::cross(a, b)), glm::dot(a, b)};
}

// Within 4 eps of the angle (relative): the largest seen is 2, over these samples and over 5
// million more (tiny angles: the pair's rescaling, the series and the sum each round once; near
// pi: pi's own rounding).
TEST(TableAngle, ArcAngleAgreesWithAtan2OverTheHalfTurn) {
  std::mt19937_64 rng(19);
  std::uniform_real_distribution<double> uniform(0.0, kPi), log_angle(-15.0, 0.0);
  std::vector<double> thetas;
  for (int i = 0; i < 100000; ++i) {
    thetas.push_back(uniform(rng));
    const double small = std::pow(10.0, log_angle(rng));
    thetas.insert(thetas.end(), {small, kPi - small, 0.5 * kPi + small, 0.5 * kPi - small});
  }
  for (double theta : thetas) {
    const SinCos p = unit_pair_at(theta, rng);
    expect_within_ulps(arc_angle(p.s, p.c), std::atan2(p.s, p.c), 4.0, "arc_angle", p.s, p.c);
  }
  // Exact unit pairs at every bin edge (and either side), mirrored into all four octants.
  for (int j = 1; j < kAngleTableBins; ++j) {
    const double u = kAngleTable[j].sin;
    for (double du : {0.0, -1e-16, 1e-16, 1e-9}) {
      const double s = u + du, c = std::sqrt(1.0 - s * s);
      for (const SinCos& p : {SinCos{s, c}, SinCos{c, s}, SinCos{c, -s}, SinCos{s, -c}})
        expect_within_ulps(arc_angle(p.s, p.c), std::atan2(p.s, p.c), 4.0, "arc_angle", p.s, p.c);
    }
  }
  // The ends and the middle, and denormal sines (the arc of a far, tiny patch's edge): there
  // theta / sin, what Lambert's edge needs, is 1.
  EXPECT_EQ(arc_angle(0.0, 1.0), 0.0);
  EXPECT_EQ(arc_angle(0.0, -1.0), std::atan2(0.0, -1.0));
  EXPECT_NEAR(arc_angle(1.0, 0.0), 0.5 * kPi, 1e-16);
  EXPECT_NEAR(arc_angle(1.0, -0.0), 0.5 * kPi, 1e-16);
  for (double s : {5e-324, 1e-310, 1e-300, 1e-200, 1e-20, 1e-9}) {
    EXPECT_EQ(arc_angle(s, 1.0) / s, 1.0) << s;
    const double near_pi = arc_angle(s, -1.0);
    expect_within_ulps(near_pi, std::atan2(s, -1.0), 2.0, "arc_angle", s, -1.0);
  }
  const double c45 = std::sqrt(0.5);
  expect_within_ulps(arc_angle(c45, c45), 0.25 * kPi, 1.0, "arc_angle", c45, c45);
  expect_within_ulps(arc_angle(c45, -c45), 0.75 * kPi, 1.0, "arc_angle", c45, -c45);
}

TEST(TableAngle, ArcAngleHandsOtherPairsToAtan2) {
  // Not of unit length (any scale, zero), a negative sine (-0 too), NaN: atan2's own answer.
  for (const auto& [s, c] : std::vector<std::pair<double, double>>{{3.0, 4.0},
                                                                   {1e-300, 1e-300},
                                                                   {0.0, 0.0},
                                                                   {0.0, -0.0},
                                                                   {0.6, 0.8 * (1 + 1e-8)},
                                                                   {-0.6, 0.8},
                                                                   {-0.0, -1.0},
                                                                   {2.0, -1e300}}) {
    EXPECT_EQ(arc_angle(s, c), std::atan2(s, c)) << s << " " << c;
  }
  EXPECT_TRUE(std::isnan(arc_angle(std::nan(""), 1.0)));
  EXPECT_TRUE(std::isnan(arc_angle(1.0, std::nan(""))));
}

TEST(TableAngle, DirectionAngleAgreesWithAtan2InEveryQuadrant) {
  std::mt19937_64 rng(18);
  std::uniform_real_distribution<double> angle(-kPi, kPi), log_r(-8.0, 3.0);
  for (int i = 0; i < 100000; ++i) {
    const double a = angle(rng), r = std::pow(10.0, log_r(rng));
    const double x = r * std::cos(a), y = r * std::sin(a);
    expect_within_ulps(direction_angle(y, x), std::atan2(y, x), 4.0, "direction_angle", y, x);
  }
  // The axes and the diagonals exactly where atan2 is exact.
  EXPECT_EQ(direction_angle(0.0, 1.0), 0.0);
  EXPECT_EQ(direction_angle(0.0, 0.0), 0.0);
  EXPECT_NEAR(direction_angle(1.0, 0.0), 0.5 * kPi, 1e-16);
  EXPECT_NEAR(direction_angle(0.0, -1.0), kPi, 1e-16);
  EXPECT_NEAR(direction_angle(-1.0, 0.0), -0.5 * kPi, 1e-16);
  EXPECT_NEAR(direction_angle(-2.0, -2.0), -0.75 * kPi, 2e-16);
}

TEST(TableAngle, UnitDirectionAngleAgreesWithAtan2InEveryQuadrant) {
  // Unit vectors normalised in double (as the table rung's directions are): within 4 eps of
  // atan2, as arc_angle.
  std::mt19937_64 rng(20);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  for (int i = 0; i < 100000; ++i) {
    const glm::dvec2 u = glm::normalize(glm::dvec2(std::cos(angle(rng)), std::sin(angle(rng))));
    expect_within_ulps(unit_direction_angle(u.y, u.x), std::atan2(u.y, u.x), 4.0,
                       "unit_direction_angle", u.y, u.x);
  }
  EXPECT_EQ(unit_direction_angle(0.0, 1.0), 0.0);
  EXPECT_EQ(unit_direction_angle(-0.0, -1.0), std::atan2(0.0, -1.0));
  EXPECT_NEAR(unit_direction_angle(-1.0, 0.0), -0.5 * kPi, 1e-16);
}

}  // namespace
}  // namespace luxgrid
