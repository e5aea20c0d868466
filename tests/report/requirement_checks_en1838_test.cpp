// EN 1838's checks of the emergency scene [EN1838]: the limits per role (1 lx and 40:1 on a route's
// centre line, 0.5 lx on its band, 0.5 lx and 40:1 on an open area), exactly at a limit met, the
// ratio of a dark surface not calculated, and how the checks show in results.json and the report.
#include <gtest/gtest.h>

#include "calc/statistics.h"
#include "report/compliance_table.h"
#include "report/requirement_checks_en1838.h"
#include "util/error.h"

namespace luxgrid::report {
namespace {

using calc::EmergencyRole;

calc::SurfaceResult surface(const std::string& name, std::vector<double> E) {
  calc::SurfaceResult s;
  s.grid.name = name;
  s.grid.points.assign(E.size(), Vec3(0.0));
  s.E = std::move(E);
  s.stats = calc::compute_statistics(s.E);
  return s;
}

calc::Results results(std::vector<calc::SurfaceResult> surfaces) {
  calc::Results r;
  r.scene = calc::LightingScene::emergency;
  r.surfaces = std::move(surfaces);
  return r;
}

const std::vector<calc::EmergencySurface> kSurfaces = {
    {"exit centre line", "exit", EmergencyRole::route_centre_line},
    {"exit band", "exit", EmergencyRole::route_band},
    {"hall", "hall", EmergencyRole::open_area}};

TEST(En1838Checks, LimitsPerRoleExactlyAtTheLimitMet) {
  // Centre line: Emin 1 lx exactly, Emax 40 lx: both limits exactly met. Band: 0.5 lx exactly.
  // Open area: Emin 0.49 lx (not met by 0.01 lx), Emax 19.6 lx (ratio 40, met).
  const auto checks =
      check_en1838(results({surface("exit centre line", {1.0, 40.0, 7.0}),
                            surface("exit band", {0.5, 3.0}), surface("hall", {0.49, 19.6, 2.0})}),
                   kSurfaces);
  ASSERT_EQ(checks.size(), 5u);
  EXPECT_EQ(checks[0].quantity, "Emin");
  EXPECT_EQ(checks[0].required, 1.0);
  EXPECT_TRUE(checks[0].met);
  EXPECT_EQ(checks[0].role, "escape route centre line");
  EXPECT_EQ(checks[0].source, "EN 1838:2013 clause 4.2");
  EXPECT_EQ(checks[1].quantity, kDiversityQuantity);
  EXPECT_TRUE(checks[1].upper_limit);
  EXPECT_DOUBLE_EQ(checks[1].achieved, 40.0);
  EXPECT_TRUE(checks[1].met);
  EXPECT_EQ(checks[1].source, "EN 1838:2013 clause 4.2");
  EXPECT_EQ(checks[2].required, 0.5);
  EXPECT_TRUE(checks[2].met);
  EXPECT_EQ(checks[2].role, "escape route central band");
  EXPECT_FALSE(checks[3].met);
  EXPECT_NEAR(checks[3].margin, -0.01, 1e-15);
  EXPECT_NEAR(checks[3].margin_rel, -0.02, 1e-14);
  EXPECT_EQ(checks[3].source, "EN 1838:2013 clause 4.3");
  EXPECT_NEAR(checks[4].achieved, 40.0, 1e-13);
  EXPECT_TRUE(checks[4].met);
  EXPECT_FALSE(all_met(checks));
}

TEST(En1838Checks, RatioAboveFortyNotMetAndUnboundedNotCalculated) {
  const auto checks =
      check_en1838(results({surface("exit centre line", {1.0, 41.0}),
                            surface("exit band", {0.0, 1.0}), surface("hall", {0.0, 2.0})}),
                   kSurfaces);
  EXPECT_TRUE(checks[0].met);
  EXPECT_FALSE(checks[1].met);
  EXPECT_DOUBLE_EQ(checks[1].margin, -1.0);  // 40 - 41
  EXPECT_FALSE(checks[2].met);               // band Emin 0
  EXPECT_FALSE(checks[4].calculated);        // open area Emin 0: Emax / Emin unbounded
  EXPECT_EQ(checks[4].note, "Emin is 0 lx, so Emax / Emin is unbounded");
  const auto j = check_to_json(checks[4]);
  EXPECT_TRUE(j["achieved"].is_null());
  EXPECT_EQ(j["limit"], "max");
  EXPECT_EQ(j["source"], "EN 1838:2013 clause 4.3");
}

TEST(En1838Checks, MissingSurfaceIsRefused) {
  EXPECT_THROW(check_en1838(results({surface("exit centre line", {1.0})}), kSurfaces), InputError);
}

TEST(En1838Checks, ReportTableNamesTheStandardAndTheRatio) {
  const auto checks =
      check_en1838(results({surface("exit centre line", {2.0, 8.0}),
                            surface("exit band", {1.0, 8.0}), surface("hall", {1.0, 4.0})}),
                   kSurfaces);
  ASSERT_TRUE(all_met(checks));
  const std::string html = compliance_table_html(checks);
  EXPECT_NE(html.find("<h2>Compliance: emergency lighting (EN 1838)</h2>"), std::string::npos);
  EXPECT_NE(html.find("E<sub>max</sub> / E<sub>min</sub>"), std::string::npos);
  EXPECT_NE(html.find("EN 1838:2013 clause 4.2"), std::string::npos);
  EXPECT_EQ(html.find("preset EN"), std::string::npos);  // a standard's limit is not a preset
  EXPECT_NE(html.find("data-check=\"exit centre line|Emax/Emin\" data-result=\"met\""),
            std::string::npos);
  EXPECT_NE(lighting_scene_row_html(calc::LightingScene::emergency).find("emergency (EN 1838)"),
            std::string::npos);
  EXPECT_EQ(lighting_scene_row_html(calc::LightingScene::normal), "");
  // The ratio is printed to 0.1, like the table's lux values: 8 / 2 = 4.0.
  EXPECT_NE(html.find(">4.0<"), std::string::npos);
}

}  // namespace
}  // namespace luxgrid::report
