// `luxgrid report`: a calculation's outputs written again from its results.json alone are the
// bytes `calc` wrote (CSVs, plots, report.html; SOURCE_DATE_EPOCH set), a colour scale changes
// the plots exactly as `calc --scale` does, and a results file that is malformed or not luxgrid's
// is refused with the file and the JSON pointer (exit 2).
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_support.h"

// In cli_support.h's namespace, so its helpers need no using-declarations here.
namespace luxgrid::test {
namespace {

namespace fs = std::filesystem;

CommandResult run(const std::string& args) { return luxgrid_at_fixed_date("--threads 2 " + args); }

// `calc` then `report` into another folder: every file the report writes is calc's to the byte.
class ReportOfExample : public ::testing::TestWithParam<std::string> {};

TEST_P(ReportOfExample, WritesTheBytesCalcWrote) {
  const fs::path dir = scratch(GetParam());
  const fs::path project = fs::path(LUXGRID_SOURCE_DIR) / "examples" / GetParam() / "project.json";
  const auto calc = run("calc " + quote(project) + " -o " + quote(dir / "calc") + " --part-plots");
  ASSERT_EQ(calc.code, 0) << calc.output;
  const auto report = run("report " + quote(dir / "calc" / "results.json") + " -o " +
                          quote(dir / "report") + " --part-plots");
  ASSERT_EQ(report.code, 0) << report.output;
  const std::set<std::string> written = entries(dir / "report");
  size_t csv = 0, png = 0;
  for (const auto& f : entries(dir / "calc")) {
    if (f == "timing.json" || f == ".luxgrid-output") continue;
    EXPECT_TRUE(written.count(f)) << f << " not written by report";
    EXPECT_TRUE(same_bytes(dir / "calc" / f, dir / "report" / f)) << f;
    csv += fs::path(f).extension() == ".csv";
    png += fs::path(f).extension() == ".png";
  }
  EXPECT_GT(csv, 0u);
  EXPECT_GT(png, 0u);
  EXPECT_TRUE(written.count("report.html"));
  EXPECT_TRUE(written.count("scene.glb"));  // from results.json alone, calc's bytes (above)
}

INSTANTIATE_TEST_SUITE_P(Examples, ReportOfExample,
                         ::testing::Values("office", "lshape", "openplan", "daylight_classroom"));

TEST(ReportCommand, AScaleChangesThePlotsAsCalcDoes) {
  const fs::path dir = scratch("scale");
  const fs::path project = fs::path(LUXGRID_SOURCE_DIR) / "examples/office/project.json";
  ASSERT_EQ(run("calc " + quote(project) + " -o " + quote(dir / "plain")).code, 0);
  ASSERT_EQ(run("calc " + quote(project) + " -o " + quote(dir / "scaled") + " --scale 0:1000").code,
            0);
  const auto r = run("report " + quote(dir / "plain" / "results.json") + " -o " +
                     quote(dir / "rescaled") + " --scale 0:1000");
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* f : {"workplane.png", "room_floor.png", "report.html", "scene.glb"}) {
    EXPECT_TRUE(same_bytes(dir / "scaled" / f, dir / "rescaled" / f)) << f;
    EXPECT_FALSE(same_bytes(dir / "plain" / f, dir / "rescaled" / f)) << f;
  }
  // Into its own folder (the default): results.json unchanged, the plots on the new scale.
  const std::string results = read_file(dir / "plain" / "results.json");
  const auto here = run("report " + quote(dir / "plain" / "results.json") + " --scale 0:1000");
  ASSERT_EQ(here.code, 0) << here.output;
  EXPECT_EQ(read_file(dir / "plain" / "results.json"), results);
  EXPECT_TRUE(same_bytes(dir / "scaled" / "workplane.png", dir / "plain" / "workplane.png"));
}

TEST(ReportCommand, RefusesAForeignOrMalformedResultsFile) {
  const fs::path dir = scratch("refused");
  const fs::path project = fs::path(LUXGRID_SOURCE_DIR) / "examples/office/project.json";
  ASSERT_EQ(run("calc " + quote(project) + " -o " + quote(dir / "calc")).code, 0);
  const nlohmann::json good = nlohmann::json::parse(read_file(dir / "calc" / "results.json"));
  struct Case {
    std::string name;
    nlohmann::json doc;
    std::string expected;  // in the message, after the file's name
  };
  std::vector<Case> cases;
  nlohmann::json foreign = good;
  foreign["format"] = "someone-else/1";
  cases.push_back({"foreign", foreign, "/format: not a luxgrid results file"});
  nlohmann::json old = good;
  old.erase("report_input");
  cases.push_back({"old", old, "/report_input: missing"});
  nlohmann::json wrong = good;
  wrong["report_input"]["rooms"][0]["height"] = "3 m";
  cases.push_back({"wrong", wrong, "/report_input/rooms/0/height: type must be number"});
  nlohmann::json missing = good;
  missing["plan"].erase("near_far");
  cases.push_back({"missing", missing, "/plan: key 'near_far' not found"});
  nlohmann::json short_array = good;
  short_array["surfaces"][0]["E"].erase(0);
  cases.push_back({"short", short_array, "/surfaces/0: the per-point arrays differ in length"});
  for (const Case& c : cases) {
    const fs::path file = dir / (c.name + ".json");
    write_file(file, c.doc.dump(1));
    const auto r = run("report " + quote(file) + " -o " + quote(dir / (c.name + ".out")));
    EXPECT_EQ(r.code, 2) << c.name << ": " << r.output;
    EXPECT_NE(r.output.find(file.string() + " " + c.expected), std::string::npos)
        << c.name << ": " << r.output;
    EXPECT_FALSE(fs::exists(dir / (c.name + ".out"))) << c.name;
  }
  // Not JSON at all.
  write_file(dir / "text.json", "{\"format\": ");
  const auto r = run("report " + quote(dir / "text.json") + " -o " + quote(dir / "text.out"));
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("text.json"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace luxgrid::test
