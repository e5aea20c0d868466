// EN 17037's checks, results.json object, terminal table and report table
// (report/en17037_checks, report/en17037_html) from an assessment of a hand-counted field: the
// asked level's two checks with their shares of the plane, the JSON read back to the same
// values, and the tables showing each level's verdict.
#include <gtest/gtest.h>

#include "report/en17037_checks.h"
#include "report/en17037_html.h"

namespace luxgrid::report {
namespace {

// 10 points at E_v,d,med 10 000 lx: DF >= 3 % at 6 (60 %), >= 1 % at 9 (90 %), >= 5 % at 2.
daylight::En17037Assessment ten_points(daylight::En17037Level asked) {
  daylight::En17037Assessment a;
  a.median_external_diffuse_lx = 10000.0;
  a.asked = asked;
  a.planes.push_back(daylight::assess_en17037_plane("wp", {0.5, 1, 2, 2, 3, 3, 4, 4, 5, 6}, {},
                                                    false, a.median_external_diffuse_lx));
  return a;
}

TEST(En17037Report, ChecksOfTheAskedLevel) {
  const auto checks = en17037_checks(ten_points(daylight::En17037Level::minimum));
  ASSERT_EQ(checks.size(), 2u);
  EXPECT_EQ(checks[0].quantity, kEn17037TargetQuantity);
  EXPECT_EQ(checks[0].required, 50.0);
  EXPECT_DOUBLE_EQ(checks[0].achieved, 60.0);
  EXPECT_TRUE(checks[0].met);
  EXPECT_DOUBLE_EQ(checks[0].margin, 10.0);
  EXPECT_EQ(checks[1].quantity, kEn17037MinimumTargetQuantity);
  EXPECT_EQ(checks[1].required, 95.0);
  EXPECT_DOUBLE_EQ(checks[1].achieved, 90.0);
  EXPECT_FALSE(checks[1].met);  // 90 % of the plane at DF >= 1 %, 95 % asked
  EXPECT_FALSE(all_met(checks));
  EXPECT_EQ(checks[0].source, "EN 17037:2018 Annex A, minimum level");
  EXPECT_EQ(checks[0].note, "DF >= 3.00 % (300 lx at 10000 lx outside)");
  EXPECT_EQ(requirement_unit(checks[0].quantity), " %");
  // The terminal's line of a check.
  EXPECT_NE(format_checks(checks).find("DF>=D_TM  required >= 95 %  achieved 90 %  NOT MET"),
            std::string::npos)
      << format_checks(checks);
}

TEST(En17037Report, JsonReadBack) {
  const auto a = ten_points(daylight::En17037Level::medium);
  const nlohmann::json j = en17037_to_json(a);
  EXPECT_EQ(j.at("level_asked"), "medium");
  EXPECT_FALSE(j.at("met").get<bool>());
  EXPECT_TRUE(j.at("planes")[0].at("level_achieved").is_null());
  const auto b = en17037_from_json(j);
  EXPECT_EQ(en17037_to_json(b), j);
  EXPECT_EQ(b.planes[0].levels[0].target.fraction, 0.6);
  EXPECT_THROW(en17037_from_json(nlohmann::json::object()), nlohmann::json::exception);
}

TEST(En17037Report, Tables) {
  const auto a = ten_points(daylight::En17037Level::minimum);
  const std::string text = format_en17037(a);
  EXPECT_NE(text.find("wp (side-lit, 10 points): DF average 3.05 %, minimum 0.50 %, uniformity "
                      "0.164; level reached: none"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("minimum   300 lx  DF >=  3.00 %  over  50 % required,  60.0 % reached  met"),
            std::string::npos)
      << text;
  const std::string html = en17037_table_html(a);
  EXPECT_NE(html.find("<tr data-level=\"minimum\"><td rowspan=\"2\"><b>minimum (asked)</b>"),
            std::string::npos);
  EXPECT_NE(html.find("<td class=\"num\">90.0 %</td><td class=\"notmet\">not met</td>"),
            std::string::npos)
      << html;
}

}  // namespace
}  // namespace luxgrid::report
