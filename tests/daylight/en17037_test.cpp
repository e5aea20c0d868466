// EN 17037 daylight provision by the daylight-factor method (calc/daylight/en17037): the target
// daylight factors from a site's median, the fraction of a plane reaching each on synthetic
// daylight-factor fields whose fractions are counted by hand, the levels' decisions at their
// boundaries (a point exactly at a target, a fraction exactly at 50 % and 95 %) and the top-lit
// rule [EN17037, Annex A].
#include <gtest/gtest.h>

#include <cmath>

#include "calc/daylight/en17037.h"

namespace luxgrid::daylight {
namespace {

// 20 points at E_v,d,med = 10 000 lx, where the targets are DF 3 / 1 % (minimum), 5 / 3 %
// (medium), 7.5 / 5 % (high). By hand: DF >= 1 at 19 points (95 %), >= 3 at 14 (70 %), >= 5 at
// 8 (40 %), >= 7.5 at 3 (15 %). The sum is 81: average 4.05 %, minimum 0.5 %.
const std::vector<double> kField = {0.5, 1, 1, 1, 2, 2, 3, 3,   3, 3,
                                    4,   4, 5, 5, 5, 6, 7, 7.5, 8, 10};

TEST(En17037, TargetDaylightFactors) {
  EXPECT_DOUBLE_EQ(target_daylight_factor_percent(300.0, 10000.0), 3.0);
  EXPECT_DOUBLE_EQ(target_daylight_factor_percent(100.0, 14000.0), 100.0 / 140.0);
  EXPECT_EQ(en17037_targets(En17037Level::minimum).target_lx, 300.0);
  EXPECT_EQ(en17037_targets(En17037Level::minimum).minimum_target_lx, 100.0);
  EXPECT_EQ(en17037_targets(En17037Level::medium).target_lx, 500.0);
  EXPECT_EQ(en17037_targets(En17037Level::medium).minimum_target_lx, 300.0);
  EXPECT_EQ(en17037_targets(En17037Level::high).target_lx, 750.0);
  EXPECT_EQ(en17037_targets(En17037Level::high).minimum_target_lx, 500.0);
  EXPECT_EQ(en17037_level_from_name("medium"), En17037Level::medium);
  EXPECT_FALSE(en17037_level_from_name("Medium").has_value());
}

TEST(En17037, FractionsOfAHandCountedField) {
  const En17037PlaneResult r = assess_en17037_plane("wp", kField, {}, false, 10000.0);
  EXPECT_EQ(r.points, 20u);
  EXPECT_DOUBLE_EQ(r.DF_average_percent, 4.05);
  EXPECT_EQ(r.DF_min_percent, 0.5);
  EXPECT_DOUBLE_EQ(r.uniformity, 0.5 / 4.05);
  const auto& minimum = r.levels[0];
  EXPECT_EQ(minimum.target.daylight_factor_percent, 3.0);
  EXPECT_DOUBLE_EQ(minimum.target.fraction, 14.0 / 20.0);
  EXPECT_DOUBLE_EQ(minimum.minimum_target.fraction, 19.0 / 20.0);
  EXPECT_EQ(minimum.target.required_fraction, 0.5);
  EXPECT_EQ(minimum.minimum_target.required_fraction, 0.95);
  EXPECT_TRUE(minimum.met);  // 70 % >= 50 %, and 95 % exactly at 95 %
  const auto& medium = r.levels[1];
  EXPECT_DOUBLE_EQ(medium.target.fraction, 8.0 / 20.0);
  EXPECT_DOUBLE_EQ(medium.minimum_target.fraction, 14.0 / 20.0);
  EXPECT_FALSE(medium.target.met);
  EXPECT_FALSE(medium.met);
  const auto& high = r.levels[2];
  EXPECT_DOUBLE_EQ(high.target.fraction, 3.0 / 20.0);  // 7.5 exactly at the target counts
  EXPECT_DOUBLE_EQ(high.minimum_target.fraction, 8.0 / 20.0);
  ASSERT_TRUE(r.achieved.has_value());
  EXPECT_EQ(*r.achieved, En17037Level::minimum);
}

// Inactive points (outside the plane, in an obstacle) are no part of it.
TEST(En17037, InactivePointsLeftOut) {
  std::vector<double> df = kField;
  std::vector<bool> active(df.size(), true);
  df.push_back(0.0), active.push_back(false);
  df.push_back(0.0), active.push_back(false);
  const En17037PlaneResult r = assess_en17037_plane("wp", df, active, false, 10000.0);
  EXPECT_EQ(r.points, 20u);
  EXPECT_EQ(r.DF_min_percent, 0.5);
  EXPECT_TRUE(r.levels[0].met);
}

// A point just below a target does not reach it; one fraction point short of 95 % fails.
TEST(En17037, DecisionsAtTheBoundaries) {
  std::vector<double> df = kField;
  df[1] = 1.0 - 1e-6;  // now 18 of 20 reach DF 1 %: 90 % < 95 %
  const En17037PlaneResult r = assess_en17037_plane("wp", df, {}, false, 10000.0);
  EXPECT_DOUBLE_EQ(r.levels[0].minimum_target.fraction, 18.0 / 20.0);
  EXPECT_FALSE(r.levels[0].met);
  EXPECT_FALSE(r.achieved.has_value());
  // Exactly half the plane at DF >= 3 % meets E_T: 10 points at 3, 10 at 1.
  std::vector<double> half(20, 1.0);
  for (int k = 0; k < 10; ++k) half[k] = 3.0;
  const En17037PlaneResult h = assess_en17037_plane("wp", half, {}, false, 10000.0);
  EXPECT_DOUBLE_EQ(h.levels[0].target.fraction, 0.5);
  EXPECT_TRUE(h.levels[0].met);
  // 9 of 20 (45 %) does not.
  half[9] = 2.999;
  EXPECT_FALSE(assess_en17037_plane("wp", half, {}, false, 10000.0).levels[0].met);
  // A target daylight factor that is no exact double (300 / 14000): a point computed as
  // 300 / 14000 * 100 in another order still reaches it.
  const double at_target = 300.0 / 14000.0 * 100.0;
  std::vector<double> at(20, at_target);
  EXPECT_EQ(assess_en17037_plane("wp", at, {}, false, 14000.0).levels[0].target.fraction, 1.0);
}

// Top-lit: E_T too over 95 % of the plane. The field's 70 % at DF >= 3 % then fails minimum;
// a field with 19 of 20 points at DF >= 3 % meets it.
TEST(En17037, TopLitRule) {
  EXPECT_EQ(target_fraction(false), 0.5);
  EXPECT_EQ(target_fraction(true), 0.95);
  const En17037PlaneResult r = assess_en17037_plane("wp", kField, {}, true, 10000.0);
  EXPECT_TRUE(r.top_lit);
  EXPECT_EQ(r.levels[0].target.required_fraction, 0.95);
  EXPECT_FALSE(r.levels[0].target.met);
  EXPECT_FALSE(r.achieved.has_value());
  std::vector<double> roof(20, 3.0);
  roof[0] = 1.0;
  const En17037PlaneResult t = assess_en17037_plane("wp", roof, {}, true, 10000.0);
  EXPECT_TRUE(t.levels[0].met);
  EXPECT_EQ(*t.achieved, En17037Level::minimum);
  // Side-lit, the same field meets the medium level's minimum target (95 % at DF >= 3 %) but
  // not its target (0 % at DF >= 5 %).
  const En17037PlaneResult s = assess_en17037_plane("wp", roof, {}, false, 10000.0);
  EXPECT_TRUE(s.levels[1].minimum_target.met);
  EXPECT_FALSE(s.levels[1].target.met);
}

// A higher level is reached only with the ones below it; an empty plane reaches none.
TEST(En17037, LevelsInOrder) {
  const std::vector<double> bright(10, 8.0);  // every target of every level at 10 000 lx
  EXPECT_EQ(*assess_en17037_plane("wp", bright, {}, false, 10000.0).achieved, En17037Level::high);
  const En17037PlaneResult none = assess_en17037_plane("wp", {}, {}, false, 10000.0);
  EXPECT_EQ(none.points, 0u);
  EXPECT_FALSE(none.levels[0].met);
  EXPECT_FALSE(none.achieved.has_value());
}

}  // namespace
}  // namespace luxgrid::daylight
