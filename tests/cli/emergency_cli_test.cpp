// Emergency lighting through the binary [EN1838]: the corridor case (cases/emergency_corridor,
// values derived by hand in its README) in its emergency scene, the same project with
// `--scene normal`, and `--check` exiting 3 when the emergency output is too low.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

namespace {

namespace fs = std::filesystem;
using luxgrid::test::luxgrid;
using luxgrid::test::quote;
using luxgrid::test::read_file;
using luxgrid::test::scratch;
using luxgrid::test::write_file;

const fs::path kCase = fs::path(LUXGRID_SOURCE_DIR) / "cases/emergency_corridor/project.json";

// E on the corridor's centre line at x (README): isotropic 50 cd at x = 2 m, Lambertian 40 cd at
// x = 8 m, both 2.5 m above the floor.
double centre_line_E(double x) {
  const double h = 2.5;
  const double d2_iso = h * h + (x - 2.0) * (x - 2.0), d2_lam = h * h + (x - 8.0) * (x - 8.0);
  return 50.0 * h / std::pow(d2_iso, 1.5) + 40.0 * h * h / (d2_lam * d2_lam);
}

const nlohmann::json* surface(const nlohmann::json& j, const std::string& name) {
  for (const auto& s : j["surfaces"]) {
    if (s["name"] == name) return &s;
  }
  return nullptr;
}

TEST(EmergencyCli, CorridorChecksMetInTheEmergencyScene) {
  const fs::path out = scratch("em") / "out";
  const auto r = luxgrid("calc " + quote(kCase) + " -o " + quote(out) + " --check");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("exit centre line     Emax/Emin required <= 40"), std::string::npos)
      << r.output;
  const auto j = nlohmann::json::parse(read_file(out / "results.json"));
  EXPECT_EQ(j["scene"], "emergency");
  EXPECT_EQ(j["requirements_met"], true);
  const auto* centre = surface(j, "exit centre line");
  ASSERT_NE(centre, nullptr);
  ASSERT_EQ((*centre)["E"].size(), 11u);
  // Exact to double rounding (the far field is exact for a point source, and no reflected light).
  for (int x = 0; x <= 10; ++x) {
    EXPECT_NEAR((*centre)["E"][x].get<double>(), centre_line_E(x), 1e-9 * centre_line_E(x)) << x;
    EXPECT_EQ((*centre)["E_indirect"][x].get<double>(), 0.0);
  }
  const auto& checks = (*centre)["requirements"];
  ASSERT_EQ(checks.size(), 2u);
  EXPECT_EQ(checks[0]["quantity"], "Emin");
  EXPECT_NEAR(checks[0]["achieved"].get<double>(), centre_line_E(10), 1e-9);
  EXPECT_EQ(checks[1]["quantity"], "Emax/Emin");
  EXPECT_NEAR(checks[1]["achieved"].get<double>(), centre_line_E(2) / centre_line_E(10), 1e-9);
  EXPECT_EQ((*surface(j, "hall"))["requirements"].size(), 2u);
  const std::string html = read_file(out / "report.html");
  EXPECT_NE(html.find("Compliance: emergency lighting (EN 1838)"), std::string::npos);
  EXPECT_NE(html.find("data-meta=\"scene\""), std::string::npos);
  // The CSV of the centre line holds the same values, horizontal, on the floor.
  const std::string csv = read_file(out / "exit_centre_line.csv");
  EXPECT_NE(csv.find(",horizontal"), std::string::npos) << csv.substr(0, 300);
}

TEST(EmergencyCli, SceneNormalAddsTheOtherLuminaireAndMakesNoEmergencyChecks) {
  const fs::path out = scratch("normal") / "out";
  const auto r = luxgrid("calc " + quote(kCase) + " -o " + quote(out) + " --scene normal --check");
  ASSERT_EQ(r.code, 0) << r.output;
  const auto j = nlohmann::json::parse(read_file(out / "results.json"));
  EXPECT_EQ(j["scene"], "normal");
  EXPECT_FALSE(j.contains("requirements_met"));
  // At x = 5 the general luminaire alone gives 500 cd / 2.5^2 = 80 lx directly below it.
  EXPECT_GT((*surface(j, "exit centre line"))["E"][5].get<double>(), 80.0);
}

TEST(EmergencyCli, CheckExitsThreeWhenTheEmergencyOutputIsTooLow) {
  // A tenth of the case's emergency output: the centre line's Emin falls to 0.26 lx, below 1 lx.
  auto project = nlohmann::json::parse(read_file(kCase));
  project["luminaires"][0]["emergency"]["fraction"] = 0.01;
  project["photometry"]["module"]["intensity_cd"] = 4.0;
  const fs::path dir = scratch("low");
  write_file(dir / "low.json", project.dump());
  const auto r = luxgrid("calc " + quote(dir / "low.json") + " --check --no-report");
  EXPECT_EQ(r.code, 3) << r.output;
  EXPECT_NE(r.output.find("NOT MET"), std::string::npos) << r.output;
}

TEST(EmergencyCli, EmergencySceneWithoutEmergencyLuminairesIsBadInput) {
  auto project = nlohmann::json::parse(read_file(kCase));
  for (auto& l : project["luminaires"]) l.erase("emergency");
  const fs::path dir = scratch("none");
  write_file(dir / "none.json", project.dump());
  const auto r = luxgrid("calc " + quote(dir / "none.json"));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("none.json: the emergency scene has no light"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir / "none.out"));
}

}  // namespace
