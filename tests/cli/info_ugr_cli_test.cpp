// `luxgrid info FILE --ugr`: the CIE 190 table in text and JSON agree, the text prints the values
// for the file's lamp flux (the 1000 lm table plus 8 log10(F / 1000)), and a file without a
// luminous area is refused with exit 2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace {

const std::string kMirel =
    std::string(LUXGRID_SOURCE_DIR) + "/tests/data/photometry/ldt/zumtobel_mirel_isym4.ldt";

TEST(InfoUgrCli, TextAndJsonAgree) {
  const auto j = luxgrid::test::luxgrid("info " + kMirel + " --ugr --json");
  ASSERT_EQ(j.code, 0) << j.output;
  const auto doc = nlohmann::json::parse(j.output.substr(j.output.find('{')));
  const auto& t = doc.at("ugr_table");
  ASSERT_EQ(t.at("rooms").size(), 19u);
  // The file states 2630 lm of lamp flux: correction 8 log10(2.63) = 3.36.
  EXPECT_NEAR(t.at("lamp_flux_lm").get<double>(), 2630.0, 1e-9);
  EXPECT_NEAR(t.at("correction").get<double>(), 8.0 * std::log10(2.63), 1e-9);
  const auto& row = t.at("rooms").at(10);  // 4H x 8H
  EXPECT_EQ(row.at("x_H").get<double>(), 4.0);
  EXPECT_EQ(row.at("y_H").get<double>(), 8.0);
  const double corrected = row.at("crosswise").at(0).get<double>();
  EXPECT_NEAR(corrected - row.at("crosswise_1000lm").at(0).get<double>(),
              t.at("correction").get<double>(), 1e-9);
  // The text row for 4H x 8H starts with the same value to one decimal.
  const auto text = luxgrid::test::luxgrid("info " + kMirel + " --ugr");
  ASSERT_EQ(text.code, 0);
  char expected[64];
  std::snprintf(expected, sizeof expected, " 4H x  8H  %5.1f", corrected);
  EXPECT_NE(text.output.find(expected), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("the 1000 lm table +3.4 (8 log10(F / 1000))"), std::string::npos);
}

TEST(InfoUgrCli, PointOpeningIsRefused) {
  const std::string file = std::string(LUXGRID_SOURCE_DIR) +
                           "/tests/data/photometry/ies/mdl_rimlight_iesna91_onevalueperline.ies";
  const auto r = luxgrid::test::luxgrid("info " + file + " --ugr");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("UGR table: the file gives no luminous area"), std::string::npos)
      << r.output;
}

}  // namespace
