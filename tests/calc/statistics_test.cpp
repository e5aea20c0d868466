#include <gtest/gtest.h>

#include "calc/statistics.h"

namespace luxgrid::calc {
namespace {

TEST(Statistics, HandComputedGrid) {
  // 2 x 3 grid: min 100, max 400, mean (100+200+300+400+250+250)/6 = 250.
  const std::vector<double> E = {100, 200, 300, 400, 250, 250};
  const Statistics s = compute_statistics(E);
  EXPECT_DOUBLE_EQ(s.Emin, 100);
  EXPECT_DOUBLE_EQ(s.Emax, 400);
  EXPECT_DOUBLE_EQ(s.Eavg, 250);
  EXPECT_DOUBLE_EQ(s.U0, 0.4);
  EXPECT_DOUBLE_EQ(s.Ud, 0.25);
}

TEST(Statistics, InactivePointsAreLeftOut) {
  const std::vector<double> E = {0, 200, 300, 400};
  const Statistics s = compute_statistics(E, {false, true, true, true});
  EXPECT_DOUBLE_EQ(s.Emin, 200);
  EXPECT_DOUBLE_EQ(s.Eavg, 300);
}

TEST(Statistics, DarkSurfaceHasZeroUniformityNotNaN) {
  const Statistics s = compute_statistics({0, 0, 0});
  EXPECT_EQ(s.U0, 0.0);
  EXPECT_EQ(s.Ud, 0.0);
}

}  // namespace
}  // namespace luxgrid::calc
