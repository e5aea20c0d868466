// EN 17037 daylight provision through the binary (examples/daylight_classroom): the fractions
// in results.json recounted from the plane's DF column there, the terminal's table and the
// report's, `--check` exiting 3 exactly when the asked level is not met (a site median so high
// that every target is a trace of daylight, and so low that none is reachable), and a request
// without its median refused with exit 2 before anything is written.
#include <gtest/gtest.h>

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

const fs::path kClassroom =
    fs::path(LUXGRID_SOURCE_DIR) / "examples/daylight_classroom/project.json";

// The classroom at draft (the decisions, not the accuracy, are tested) with the request given.
fs::path classroom_with(const fs::path& dir, const nlohmann::json& en17037) {
  nlohmann::json p = nlohmann::json::parse(read_file(kClassroom));
  p["settings"]["quality"] = "draft";
  p["daylight"]["en17037"] = en17037;
  const fs::path file = dir / "project.json";
  write_file(file, p.dump(1));
  return file;
}

TEST(En17037Cli, FractionsRecountedFromTheDaylightFactors) {
  const fs::path dir = scratch("en17037");
  const fs::path project = classroom_with(dir, {{"median_external_diffuse_lx", 14000}});
  const auto r = luxgrid("--threads 2 calc " + quote(project) + " -o " + quote(dir / "out"));
  ASSERT_TRUE(r.code == 0 || r.code == 3) << r.output;
  EXPECT_NE(r.output.find("EN 17037 daylight provision (daylight-factor method, E_v,d,med 14000 "
                          "lx, level asked: minimum)"),
            std::string::npos)
      << r.output;
  const auto j = nlohmann::json::parse(read_file(dir / "out/results.json"));
  const auto& e = j.at("en17037");
  ASSERT_EQ(e.at("planes").size(), 1u);
  const auto& plane = e.at("planes")[0];
  EXPECT_EQ(plane.at("surface"), "reference plane");
  EXPECT_FALSE(plane.at("top_lit").get<bool>());
  const auto& s = j.at("surfaces")[0];
  const auto& df = s.at("DF");
  const auto& active = s.at("active");
  // The recount: targets 300 / 100, 500 / 300, 750 / 500 lx at 14 000 lx.
  const double targets[3][2] = {{300, 100}, {500, 300}, {750, 500}};
  size_t points = 0;
  double sum = 0.0;
  for (size_t i = 0; i < df.size(); ++i)
    if (active[i].get<bool>()) ++points, sum += df[i].get<double>();
  EXPECT_EQ(plane.at("points").get<size_t>(), points);
  EXPECT_NEAR(plane.at("DF_average").get<double>(), sum / points, 1e-12);
  for (int level = 0; level < 3; ++level) {
    for (int t = 0; t < 2; ++t) {
      const double d = 100.0 * targets[level][t] / 14000.0;
      size_t reaching = 0;
      for (size_t i = 0; i < df.size(); ++i)
        if (active[i].get<bool>() && df[i].get<double>() >= d) ++reaching;
      const auto& c = plane.at("levels")[level].at(t == 0 ? "target" : "minimum_target");
      EXPECT_NEAR(c.at("DF").get<double>(), d, 1e-12);
      EXPECT_NEAR(c.at("fraction").get<double>(), double(reaching) / points, 1e-12)
          << level << " " << t;
    }
  }
  // The asked level's checks among the surface's requirements, and the report's table.
  const auto& req = s.at("requirements");
  ASSERT_EQ(req.size(), 2u);
  EXPECT_EQ(req[0].at("quantity"), "DF>=D_T");
  EXPECT_EQ(req[1].at("quantity"), "DF>=D_TM");
  EXPECT_EQ(req[0].at("required"), 50.0);
  EXPECT_EQ(req[1].at("required"), 95.0);
  EXPECT_EQ(j.at("requirements_met").get<bool>(), e.at("met").get<bool>());
  const std::string html = read_file(dir / "out/report.html");
  EXPECT_NE(html.find("<h2>Daylight provision (EN 17037)</h2>"), std::string::npos);
  EXPECT_NE(html.find("data-level=\"high\""), std::string::npos);
}

TEST(En17037Cli, CheckExitsThreeWhenTheLevelIsNotMet) {
  const fs::path dir = scratch("en17037_check");
  // Every target a trace of daylight: met at every level.
  const fs::path easy =
      classroom_with(dir, {{"median_external_diffuse_lx", 1e9}, {"level", "high"}});
  const auto met = luxgrid("--threads 2 calc " + quote(easy) + " -o " + quote(dir / "a") +
                           " --check --no-report");
  EXPECT_EQ(met.code, 0) << met.output;
  EXPECT_NE(met.output.find("level reached: high"), std::string::npos) << met.output;
  // DF 30 000 % asked: nothing reaches it.
  const fs::path hard = classroom_with(dir, {{"median_external_diffuse_lx", 1}});
  const auto failed = luxgrid("--threads 2 calc " + quote(hard) + " -o " + quote(dir / "b") +
                              " --check --no-report");
  EXPECT_EQ(failed.code, 3) << failed.output;
  EXPECT_NE(failed.output.find("requirements not met (--check)"), std::string::npos);
  EXPECT_NE(failed.output.find("level reached: none"), std::string::npos);
  // Without --check the same run exits 0.
  EXPECT_EQ(
      luxgrid("--threads 2 calc " + quote(hard) + " -o " + quote(dir / "c") + " --no-report").code,
      0);
}

TEST(En17037Cli, MissingMedianRefusedBeforeAnythingIsWritten) {
  const fs::path dir = scratch("en17037_bad");
  const fs::path project = classroom_with(dir, {{"level", "medium"}});
  const auto r = luxgrid("calc " + quote(project) + " -o " + quote(dir / "out"));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find(" /daylight/en17037: missing required key "
                          "\"median_external_diffuse_lx\""),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// Every refusal of bad daylight input reaches the command line as exit 2 with its place, and no
// output folder (the loader's messages themselves: tests/project/daylight_project_test.cpp).
TEST(En17037Cli, BadDaylightInputRefusedWithItsPlace) {
  const fs::path dir = scratch("daylight_bad");
  const nlohmann::json base = nlohmann::json::parse(read_file(kClassroom));
  struct Bad {
    const char* pointer;    // the value replaced
    const char* value;      // its replacement (JSON)
    const char* place;      // where the message says the fault is
    const char* complaint;  // what it says
  };
  const Bad cases[] = {
      {"/openings/0/polygon", "[[0.6,0.1,0.9],[2.4,0,0.9],[2.4,0,2.7],[0.6,0,2.7]]",
       "/openings/0/polygon", "lies in the plane of no face"},
      {"/openings/0/polygon", "[[-1,0,0.9],[2.4,0,0.9],[2.4,0,2.7],[-1,0,2.7]]",
       "/openings/0/polygon", "crosses the edge of wall 0"},
      {"/openings/1/polygon", "[[2,0,0.9],[4.9,0,0.9],[4.9,0,2.7],[2,0,2.7]]",
       "/openings/1/polygon", "overlaps opening \"south 1\""},
      {"/daylight/sky/type", "\"overcast\"", "/daylight/sky/type", "expected a CIE general sky"},
      {"/openings/0/glazing/transmittance", "0", "/openings/0/glazing/transmittance",
       "expected a normal transmittance in (0, 1]"},
      {"/openings/0/glazing/transmittance", "0.95", "/openings/0/glazing/transmittance",
       "transmits at most 0.918"},
  };
  int n = 0;
  for (const Bad& b : cases) {
    nlohmann::json p = base;
    p[nlohmann::json::json_pointer(b.pointer)] = nlohmann::json::parse(b.value);
    const fs::path file = dir / ("bad" + std::to_string(n) + ".json");
    const fs::path out = dir / ("out" + std::to_string(n++));
    write_file(file, p.dump(1));
    const auto r = luxgrid("calc " + quote(file) + " -o " + quote(out));
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find(std::string(b.place) + ": "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(b.complaint), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out)) << b.pointer;
  }
}

// The request in a run of the normal scene (`--scene normal` over the classroom's settings): no
// EN 17037 table, no checks, and a warning that says why rather than nothing.
TEST(En17037Cli, RequestOutsideTheDaylightSceneIsWarnedAbout) {
  const fs::path dir = scratch("en17037_normal_scene");
  const fs::path project = classroom_with(dir, {{"median_external_diffuse_lx", 14000}});
  const auto run = luxgrid("--threads 2 calc " + quote(project) + " -o " + quote(dir / "out") +
                           " --scene normal --check --no-report");
  EXPECT_EQ(run.code, 0) << run.output;
  EXPECT_NE(run.output.find("EN 17037 is assessed in the daylight scene only"), std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find("level reached"), std::string::npos) << run.output;
  const nlohmann::json results = nlohmann::json::parse(read_file(dir / "out" / "results.json"));
  EXPECT_FALSE(results.contains("en17037"));
  bool warned = false;
  for (const auto& w : results.at("warnings"))
    warned = warned || w.get<std::string>().find("/daylight/en17037") != std::string::npos;
  EXPECT_TRUE(warned) << results.at("warnings").dump();
  // The classroom has no luminaires: its normal scene's zero illuminance is said, with the scene
  // that calculates its daylight.
  bool dark = false;
  for (const auto& w : results.at("warnings"))
    dark = dark || w.get<std::string>().find(
                       "/luminaires: the normal scene has no luminaires: "
                       "every illuminance is 0 lx (daylight is calculated "
                       "in the daylight scene") != std::string::npos;
  EXPECT_TRUE(dark) << results.at("warnings").dump();
}

}  // namespace
