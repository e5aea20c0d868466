// report.html's daylight section (report/daylight_section_html.h) and the openings in the plan
// view, for tests/data's daylit office (two glazed windows, an unglazed roof light, CIE sky 12
// with the sun computed for Berlin): every number the section prints compared with what
// results.json holds or with the project's geometry (the openings' areas by hand), the section
// rewritten byte for byte by `luxgrid report` from results.json alone, and absent from the
// electric-light scenes.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace {

namespace fs = std::filesystem;
using luxgrid::test::luxgrid_at_fixed_date;
using luxgrid::test::quote;
using luxgrid::test::read_file;
using luxgrid::test::scratch;

const std::string kDaylitOffice =
    std::string(LUXGRID_SOURCE_DIR) + "/tests/data/daylight_office/project.json";

std::string printed(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}
// The page's daylight section, "" when there is none.
std::string daylight_section(const std::string& page) {
  const std::size_t from = page.find("<section class=\"daylight\" id=\"daylight\">");
  if (from == std::string::npos) return "";
  return page.substr(from, page.find("</section>", from) - from);
}
// The table row (<tr ...>...</tr>) whose opening tag holds `attribute`.
std::string row(const std::string& html, const std::string& attribute) {
  const std::size_t at = html.find("<tr " + attribute);
  if (at == std::string::npos) return "";
  return html.substr(at, html.find("</tr>", at) - at);
}
std::string cell(const std::string& tr, const std::string& attribute) {
  const std::size_t at = tr.find(attribute);
  if (at == std::string::npos) return "";
  const std::size_t open = tr.find('>', at) + 1;
  return tr.substr(open, tr.find("</td>", open) - open);
}
std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(DaylightReport, TheSectionPrintsTheSkyTheOpeningsAndTheDaylightFactors) {
  const fs::path dir = scratch("daylit");
  const auto calc = luxgrid_at_fixed_date("calc " + quote(kDaylitOffice) + " -o " +
                                          quote(dir / "out") + " --quality draft");
  ASSERT_EQ(calc.code, 0) << calc.output;
  const std::string page = read_file(dir / "out" / "report.html");
  const auto results = nlohmann::json::parse(read_file(dir / "out" / "results.json"));
  const std::string s = daylight_section(page);
  ASSERT_FALSE(s.empty());

  // The sky as the plan records what the calculation used.
  const auto& d = results["plan"]["daylight"];
  ASSERT_EQ(d["sky"], "12");
  EXPECT_NE(row(s, "data-daylight=\"sky\"").find("CIE standard general sky type 12"),
            std::string::npos);
  EXPECT_NE(row(s, "data-daylight=\"diffuse_horizontal_lx\"").find("10000 lx"), std::string::npos);
  EXPECT_NE(row(s, "data-daylight=\"ground_reflectance\"").find("0.20"), std::string::npos);
  ASSERT_TRUE(d["has_sun"].get<bool>());
  EXPECT_NE(row(s, "data-daylight=\"sun_altitude_deg\"")
                .find(printed("%.1f", d["sun_altitude_deg"].get<double>())),
            std::string::npos);
  EXPECT_NE(row(s, "data-daylight=\"sun_azimuth_deg\"")
                .find(printed("%.1f", d["sun_azimuth_deg"].get<double>())),
            std::string::npos);
  // Berlin at noon on 21 June: the sun in the south, about 61 degrees up (90 - 52.52 + 23.44).
  EXPECT_NEAR(d["sun_altitude_deg"].get<double>(), 60.9, 0.5);
  EXPECT_NE(row(s, "data-daylight=\"site\"").find("latitude 52.5200&deg;, longitude 13.4000&deg;"),
            std::string::npos);
  EXPECT_NE(row(s, "data-daylight=\"local_time\"").find("2024-06-21 12:00 (UTC+1 h)"),
            std::string::npos);

  // The openings: 2 x 1.5 m windows, a 1 x 1 m roof light, as the project gives their glazing.
  const std::string left = row(s, "data-opening=\"window left\"");
  EXPECT_EQ(cell(left, "data-value=\"area_m2\""), "3.00 m&sup2;");
  EXPECT_EQ(cell(left, "data-value=\"transmittance\""), "0.80");
  EXPECT_EQ(cell(left, "data-value=\"frame_factor\""), "0.80");
  EXPECT_EQ(cell(left, "data-value=\"maintenance_factor\""), "0.90");
  EXPECT_NE(left.find("<td>wall 0</td>"), std::string::npos);
  const std::string roof = row(s, "data-opening=\"roof light\"");
  EXPECT_EQ(cell(roof, "data-value=\"area_m2\""), "1.00 m&sup2;");
  EXPECT_EQ(cell(roof, "data-value=\"transmittance\""), "unglazed");
  EXPECT_EQ(cell(roof, "data-value=\"frame_factor\""), "1.00");

  // Each surface's daylight factor statistics from results.json's per-point DF (active points),
  // and a map with the contour levels of 1, 2, 5 % that lie inside its range.
  int grids = 0;
  for (const auto& surface : results["surfaces"]) {
    const std::string name = surface["name"];
    double lo = 1e300, hi = -1e300, sum = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < surface["DF"].size(); ++i) {
      if (!surface["active"][i].get<bool>()) continue;
      const double v = surface["DF"][i];
      lo = std::min(lo, v), hi = std::max(hi, v), sum += v, ++n;
    }
    ASSERT_GT(n, 0) << name;
    const std::string tr = row(s, "data-surface=\"" + name + "\"");
    EXPECT_EQ(cell(tr, "data-stat=\"DFmin\""), printed("%.2f", lo) + " %") << name;
    EXPECT_EQ(cell(tr, "data-stat=\"DFavg\""), printed("%.2f", sum / n) + " %") << name;
    EXPECT_EQ(cell(tr, "data-stat=\"DFmax\""), printed("%.2f", hi) + " %") << name;
    if (surface["kind"] != "grid") {
      EXPECT_EQ(s.find("<figure class=\"df-map\" data-surface=\"" + name + "\""),
                std::string::npos);
      continue;
    }
    ++grids;
    std::string levels;
    for (double l : {1.0, 2.0, 5.0})
      if (l > lo && l < hi) levels += (levels.empty() ? "" : " ") + printed("%g", l);
    EXPECT_NE(
        s.find("<figure class=\"df-map\" data-surface=\"" + name + "\" data-df-levels=\"" + levels +
               "\"><img alt=\"daylight factor of " + name + "\" src=\"data:image/png;base64,iVBOR"),
        std::string::npos)
        << name << ": levels " << levels;
  }
  EXPECT_EQ(count(s, "<figure class=\"df-map\""), static_cast<std::size_t>(grids));
  EXPECT_GE(grids, 2);

  // The plan view: the two windows as bands on wall 0, the roof light as its outline.
  EXPECT_EQ(count(page, "<line class=\"daylight-opening\""), 2u);
  EXPECT_EQ(count(page, "<polygon class=\"daylight-opening\" data-opening=\"roof light\""), 1u);

  // `luxgrid report` from results.json alone writes the same page and scene (the openings and the
  // site are in its report_input).
  const auto again = luxgrid_at_fixed_date("report " + quote(dir / "out" / "results.json") +
                                           " -o " + quote(dir / "again"));
  ASSERT_EQ(again.code, 0) << again.output;
  EXPECT_TRUE(read_file(dir / "again" / "report.html") == page);
  EXPECT_TRUE(read_file(dir / "again" / "scene.glb") == read_file(dir / "out" / "scene.glb"));
}

TEST(DaylightReport, ElectricScenesHaveNoDaylightSection) {
  const fs::path dir = scratch("electric");
  // The daylit office in the normal scene: its openings are in the plan, the section is not.
  const auto normal = luxgrid_at_fixed_date("calc " + quote(kDaylitOffice) + " -o " +
                                            quote(dir / "normal") + " --scene normal");
  ASSERT_EQ(normal.code, 0) << normal.output;
  const std::string page = read_file(dir / "normal" / "report.html");
  EXPECT_EQ(daylight_section(page), "");
  EXPECT_EQ(page.find("id=\"daylight\""), std::string::npos);
  EXPECT_EQ(count(page, "class=\"daylight-opening\""), 3u);
  // A project without openings: none in the plan, none in results.json's report_input.
  const auto office = luxgrid_at_fixed_date("calc " + std::string(LUXGRID_SOURCE_DIR) +
                                            "/examples/office/project.json -o " +
                                            quote(dir / "office") + " --quality draft");
  ASSERT_EQ(office.code, 0) << office.output;
  const std::string office_page = read_file(dir / "office" / "report.html");
  EXPECT_EQ(daylight_section(office_page), "");
  EXPECT_EQ(office_page.find("daylight-opening"), std::string::npos);
  const auto input = nlohmann::json::parse(read_file(dir / "office" / "results.json"));
  EXPECT_FALSE(input["report_input"].contains("openings"));
  EXPECT_FALSE(input["report_input"].contains("daylight_site"));
}

}  // namespace
