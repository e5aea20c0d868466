// The contour lines of a map (report/false_colour.h plot_levels): the daylight factor's fixed
// levels of 1, 2 and 5 % (report/daylight_section_html.h) where the map's range holds them, in
// place of the legend's round values; requirement lines first and each value once; and an
// illuminance map's round values unchanged (isolux_levels).
#include <gtest/gtest.h>

#include "report/daylight_section_html.h"
#include "report/false_colour.h"
#include "report/isolux.h"

namespace luxgrid::report {
namespace {

std::vector<double> values(const std::vector<PlotLevel>& levels) {
  std::vector<double> out;
  for (const PlotLevel& l : levels) out.push_back(l.value);
  return out;
}

TEST(DaylightLevels, TheDaylightFactorGetsOneTwoAndFivePercentInsideItsRange) {
  EXPECT_EQ(kDaylightFactorLevels, (std::vector<double>{1.0, 2.0, 5.0}));
  PlotOverlay df;
  df.levels = kDaylightFactorLevels;
  // A range of 0.5 to 8 % holds all three; its legend's round values (0.5, 1, 2, ...) are not
  // drawn.
  const ColourScale wide = fit_scale(0.5, 8.0);
  EXPECT_EQ(values(plot_levels(df, wide, 0.5, 8.0)), (std::vector<double>{1.0, 2.0, 5.0}));
  // 0.4 to 3.7 %: 5 % is not reached; 1.2 to 1.9 %: none is; a level on the range's end is not
  // inside it.
  EXPECT_EQ(values(plot_levels(df, fit_scale(0.4, 3.7), 0.4, 3.7)),
            (std::vector<double>{1.0, 2.0}));
  EXPECT_TRUE(plot_levels(df, fit_scale(1.2, 1.9), 1.2, 1.9).empty());
  EXPECT_EQ(values(plot_levels(df, fit_scale(1.0, 4.0), 1.0, 4.0)), (std::vector<double>{2.0}));
}

TEST(DaylightLevels, RequirementsComeFirstAndEachValueOnce) {
  PlotOverlay df;
  df.levels = kDaylightFactorLevels;
  df.required_lx = {2.0, 9.0};  // 9 lies outside the range
  const auto levels = plot_levels(df, fit_scale(0.5, 8.0), 0.5, 8.0);
  ASSERT_EQ(levels.size(), 3u);
  EXPECT_EQ(levels[0].value, 2.0);
  EXPECT_TRUE(levels[0].required);
  EXPECT_EQ(levels[1].value, 1.0);
  EXPECT_FALSE(levels[1].required);
  EXPECT_EQ(levels[2].value, 5.0);
}

TEST(DaylightLevels, AnIlluminanceMapKeepsTheLegendsRoundValues) {
  const PlotOverlay lux;
  const ColourScale scale = fit_scale(120.0, 780.0);
  EXPECT_EQ(values(plot_levels(lux, scale, 120.0, 780.0)), isolux_levels(scale, 120.0, 780.0));
  EXPECT_FALSE(plot_levels(lux, scale, 120.0, 780.0).empty());
}

}  // namespace
}  // namespace luxgrid::report
