// Requirement checks against hand-computed statistics, including values exactly at the limit.
#include <gtest/gtest.h>

#include "report/requirement_checks.h"
#include "util/error.h"

namespace luxgrid::report {
namespace {

// A 2 x 1 grid "wp" with E = {400, 600}: Emin 400, Eavg 500, Emax 600, U0 0.8 (by hand).
calc::Results two_points() {
  calc::Results r;
  calc::SurfaceResult s;
  s.grid = geometry::make_plane_grid("wp", {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 2.0, 1.0, 1.0);
  s.E = {400.0, 600.0};
  s.stats = calc::compute_statistics(s.E);
  r.surfaces.push_back(s);
  return r;
}

nlohmann::json project(const nlohmann::json& req) {
  return {{"surfaces", {{{"name", "wp"}, {"requirements", req}}, {{"name", "other"}}}}};
}

TEST(Requirements, ExactlyAtTheLimitIsMet) {
  const auto checks = check_requirements(
      two_points(),
      parse_requirements(project({{"Em", 500}, {"U0", 0.8}, {"Emin", 400}, {"Emax", 600}}),
                         "p.json"));
  ASSERT_EQ(checks.size(), 4u);
  for (const auto& c : checks) {
    EXPECT_TRUE(c.met) << c.quantity;
    EXPECT_NEAR(c.margin, 0.0, 1e-12) << c.quantity;
  }
  EXPECT_EQ(checks[0].quantity, "Em");
  EXPECT_EQ(checks[3].quantity, "Emax");
  EXPECT_TRUE(checks[3].upper_limit);
  EXPECT_TRUE(all_met(checks));
}

TEST(Requirements, PassWithMargin) {
  const auto checks = check_requirements(
      two_points(), parse_requirements(project({{"Em", 400}, {"U0", 0.6}}), "p.json"));
  ASSERT_EQ(checks.size(), 2u);
  EXPECT_TRUE(checks[0].met);
  EXPECT_DOUBLE_EQ(checks[0].margin, 100.0);     // 500 - 400 lx
  EXPECT_DOUBLE_EQ(checks[0].margin_rel, 0.25);  // 100 / 400
  EXPECT_TRUE(checks[1].met);
  EXPECT_NEAR(checks[1].margin, 0.2, 1e-12);  // 0.8 - 0.6
}

TEST(Requirements, FailJustBelowAndAbove) {
  const auto checks = check_requirements(
      two_points(),
      parse_requirements(project({{"Em", 500.1}, {"Emax", 599.9}, {"Emin", 401}}), "p.json"));
  ASSERT_EQ(checks.size(), 3u);
  for (const auto& c : checks) EXPECT_FALSE(c.met) << c.quantity;
  EXPECT_NEAR(checks[0].margin, -0.1, 1e-9);  // Em: 500 - 500.1
  EXPECT_NEAR(checks[1].margin, -1.0, 1e-9);  // Emin: 400 - 401
  EXPECT_NEAR(checks[2].margin, -0.1, 1e-9);  // Emax: 599.9 - 600
  EXPECT_FALSE(all_met(checks));
  const auto j = check_to_json(checks[2]);
  EXPECT_EQ(j["limit"], "max");
  EXPECT_EQ(j["met"], false);
}

TEST(Requirements, UnknownQuantityNamesTheKey) {
  try {
    parse_requirements(project({{"Em", 500}, {"Eav", 500}}), "p.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "p.json /surfaces/0/requirements/Eav: unknown quantity \"Eav\", expected Em, U0, "
                 "Emin, Emax, Ez, Esc, "
                 "UGR_L, Ra, modelling, preset, glare_observers, cylindrical or horizontal");
  }
}

TEST(Requirements, BadValues) {
  EXPECT_THROW(parse_requirements(project({{"U0", 1.5}}), "p.json"), InputError);
  EXPECT_THROW(parse_requirements(project({{"Em", -1}}), "p.json"), InputError);
  EXPECT_THROW(parse_requirements(project({{"Em", 0}}), "p.json"), InputError);
  EXPECT_THROW(parse_requirements(project({{"Em", "500"}}), "p.json"), InputError);
  EXPECT_THROW(parse_requirements(project(nlohmann::json::array({500})), "p.json"), InputError);
}

}  // namespace
}  // namespace luxgrid::report
