// The outputs a designer reads without the docs: points left out flagged `active`, the three
// illuminances all maintained and adding up, where the results came from; and the commands as
// one meets them: a project in millimetres refused at once, warnings on stderr, a rerun that
// keeps what it was not asked to drop, commands that find their data from any folder.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/data_paths.h"
#include "report/csv.h"
#include "tests/cli/cli_support.h"
#include "util/sha256.h"

namespace {

namespace fs = std::filesystem;
using luxgrid::test::CommandResult;
using luxgrid::test::quote;
using luxgrid::test::read_file;
using luxgrid::test::scratch;

const fs::path kSource = LUXGRID_SOURCE_DIR;

// A copy of an example (project and photometry) in the test's own folder.
fs::path copy_example(const std::string& name, const fs::path& dir) {
  fs::copy(kSource / "examples" / name, dir / name, fs::copy_options::recursive);
  for (const auto& e : fs::directory_iterator(dir / name))
    if (e.path().extension() == ".out") fs::remove_all(e.path());
  return dir / name / "project.json";
}

std::vector<std::vector<std::string>> csv_rows(const fs::path& file) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(read_file(file));
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream l(line);
    while (std::getline(l, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.emplace_back();
    rows.push_back(cells);
  }
  return rows;
}

// The L-shaped office: a quarter of its workplane's box lies outside the room.
class LShapeOutputs : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(scratch("lshape"));
    project_ = new fs::path(copy_example("lshape", *dir_));
    const CommandResult r = luxgrid::test::luxgrid(
        "calc " + quote(*project_) + " --quality draft --no-report -o " + quote(*dir_ / "out"));
    ASSERT_EQ(r.code, 0) << r.output;
    results_ = new nlohmann::json(nlohmann::json::parse(read_file(*dir_ / "out/results.json")));
  }
  static const nlohmann::json& workplane() {
    for (const auto& s : (*results_)["surfaces"])
      if (s["name"] == "workplane") return s;
    throw std::runtime_error("no workplane");
  }
  static fs::path* dir_;
  static fs::path* project_;
  static nlohmann::json* results_;
};
fs::path* LShapeOutputs::dir_ = nullptr;
fs::path* LShapeOutputs::project_ = nullptr;
nlohmann::json* LShapeOutputs::results_ = nullptr;

TEST_F(LShapeOutputs, PointsOutsideTheLAreFlaggedAndLeftOutOfTheStatistics) {
  const auto& s = workplane();
  const auto& active = s["active"];
  ASSERT_EQ(active.size(), s["E"].size());
  size_t inactive = 0;
  double emin = INFINITY, sum = 0.0;
  size_t n = 0;
  for (size_t i = 0; i < active.size(); ++i) {
    if (!active[i].get<bool>()) {
      ++inactive;
      continue;
    }
    const double e = s["E"][i].get<double>();
    emin = std::min(emin, e);
    sum += e;
    ++n;
  }
  // The 8 x 8 m L minus its 4 x 4 m quarter, 0.5 m border: 7 x 7 m box, 3.5 x 3.5 m notch, so a
  // quarter of the box's points, and the cabinet's, are left out.
  EXPECT_EQ(inactive, s["points_outside"].get<size_t>() + s["points_in_obstacles"].get<size_t>());
  EXPECT_GT(s["points_outside"].get<size_t>(), active.size() / 5);
  // The statistics are over the active points only: Emin is the lowest calculated point, not the
  // 0 of a point left out. (It is low: the L's northern arm has no luminaire of its own, and at
  // draft its darkest point, beside the cabinet, gets about 1 lx.)
  EXPECT_GT(s["stats"]["Emin"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(s["stats"]["Emin"].get<double>(), emin);
  EXPECT_NEAR(s["stats"]["Eavg"].get<double>(), sum / n, 1e-9 * sum / n);
}

TEST_F(LShapeOutputs, TheCsvSaysActiveAndItsEmptyCellsGiveTheSameStatistics) {
  const auto rows = csv_rows(*dir_ / "out/workplane.csv");
  ASSERT_GT(rows.size(), 2u);
  EXPECT_EQ(rows[0], (std::vector<std::string>{"i", "j", "x", "y", "z", "nx", "ny", "nz", "active",
                                               "E_maintained_lx", "E_direct_maintained_lx",
                                               "E_indirect_maintained_lx", "quantity"}));
  double emin = INFINITY;
  size_t inactive = 0;
  for (size_t r = 1; r < rows.size(); ++r) {
    ASSERT_EQ(rows[r].size(), 13u) << r;
    if (rows[r][8] == "false") {
      ++inactive;
      EXPECT_EQ(rows[r][9], "");  // a spreadsheet's MIN and AVERAGE skip it
      continue;
    }
    ASSERT_EQ(rows[r][8], "true");
    const double e = std::stod(rows[r][9]), ed = std::stod(rows[r][10]),
                 ei = std::stod(rows[r][11]);
    emin = std::min(emin, e);
    // All three maintained: the parts add up to the total within the 6 significant digits the
    // CSV prints (two roundings of half a unit in the 6th digit each).
    EXPECT_NEAR(ed + ei, e, 1e-5 * e) << "row " << r;
    EXPECT_GT(ei, 0.0);  // reflected light ran: the sum is not trivially E_direct
  }
  EXPECT_EQ(inactive,
            std::count(workplane()["active"].begin(), workplane()["active"].end(), false));
  EXPECT_NEAR(emin, workplane()["stats"]["Emin"].get<double>(), 1e-5 * emin);
}

TEST_F(LShapeOutputs, ResultsJsonSaysWhereTheNumbersCameFrom) {
  const auto& j = *results_;
  EXPECT_EQ(j["format"], "luxgrid-results/2");
  EXPECT_EQ(j["values"], "maintained");
  EXPECT_EQ(j["quality"], "draft");  // the --quality override, not the file's "standard"
  EXPECT_DOUBLE_EQ(j["maintenance_factor"].get<double>(), 1.0);  // the project states none
  EXPECT_EQ(j["project_sha256"], luxgrid::sha256_hex(read_file(*project_)));
  const std::string version = luxgrid::test::luxgrid("--version").output;
  EXPECT_EQ("luxgrid " + j["luxgrid_version"].get<std::string>() + "\n", version);
  const auto& s = workplane();
  for (size_t i = 0; i < s["E"].size(); ++i)
    EXPECT_DOUBLE_EQ(s["E_direct"][i].get<double>() + s["E_indirect"][i].get<double>(),
                     s["E"][i].get<double>());
}

TEST(Outputs, TheMaintenanceFactorScalesEveryPart) {
  // The office states 0.8: E_direct is 0.8 x the initial direct light of the same run at 1.0.
  const fs::path dir = scratch("mf");
  const fs::path project = copy_example("office", dir);
  std::string text = read_file(project);
  const auto at = text.find("\"maintenance_factor\": 0.8");
  ASSERT_NE(at, std::string::npos);
  const fs::path initial = dir / "office/initial.json";
  luxgrid::test::write_file(initial,
                            std::string(text).replace(at, 25, "\"maintenance_factor\": 1.0"));
  for (const auto& [p, out] : {std::pair{project, dir / "a"}, std::pair{initial, dir / "b"}}) {
    const CommandResult r = luxgrid::test::luxgrid("calc " + quote(p) +
                                                   " --quality draft --no-report -o " + quote(out));
    ASSERT_EQ(r.code, 0) << r.output;
  }
  const auto a = nlohmann::json::parse(read_file(dir / "a/results.json"));
  const auto b = nlohmann::json::parse(read_file(dir / "b/results.json"));
  EXPECT_DOUBLE_EQ(a["maintenance_factor"].get<double>(), 0.8);
  for (const char* key : {"E", "E_direct", "E_indirect"}) {
    const auto& ea = a["surfaces"][0][key];
    const auto& eb = b["surfaces"][0][key];
    for (size_t i = 0; i < ea.size(); ++i)
      EXPECT_NEAR(ea[i].get<double>(), 0.8 * eb[i].get<double>(), 1e-12 * eb[i].get<double>())
          << key << " " << i;
  }
}

// The office with every length in millimetres (and the variant with reflected light off, which
// used to report Em 0.0003 lx without a word): refused at once, naming the height and the units.
TEST(Outputs, AnOfficeInMillimetresIsRefusedBeforeItIsCalculated) {
  const fs::path dir = scratch("mm");
  fs::copy(kSource / "examples/office/photometry", dir / "photometry", fs::copy_options::recursive);
  const char* office_mm = R"({
    "format": "luxgrid-project/1", "name": "office in mm",
    "settings": { "indirect": "%s", "maintenance_factor": 0.8 },
    "photometry": { "mirel": "photometry/zumtobel_mirel_isym4.ldt" },
    "rooms": [ { "name": "office", "outline": [[0, 0], [6000, 0], [6000, 4000], [0, 4000]], "height": 2800 } ],
    "luminaires": [ { "name": "panel", "photometry": "mirel",
                      "array": { "origin": [1000, 1000, 2800], "count": [3, 2], "spacing": [2000, 2000] } } ],
    "surfaces": [ { "name": "workplane", "workplane": { "room": "office", "height": 750, "border": 500 }, "spacing": 250 } ]
  })";
  for (const char* indirect : {"auto", "off"}) {
    char text[2048];
    std::snprintf(text, sizeof text, office_mm, indirect);
    luxgrid::test::write_file(dir / "mm.json", text);
    // In 1 GiB of address space: the office the unrefused run sized by its room took more
    // (it ran out of memory after 64 s), a run refused while loading takes a few tens of MB.
    const CommandResult r =
        luxgrid::test::shell("ulimit -v 1048576; " + std::string(LUXGRID_BINARY) + " calc " +
                             quote(dir / "mm.json") + " -o " + quote(dir / "out"));
    EXPECT_EQ(r.code, 2) << indirect << ": " << r.output;
    EXPECT_NE(
        r.output.find("luxgrid: error: mm.json:5:103 /rooms/0/height: the room \"office\" is 2800 "
                      "m high, more than "
                      "the limit of 1000 m for a room; the lengths look like millimetres"),
        std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(dir / "out"));  // nothing written
    // Refused while loading, before anything is sized by the room: the loader's message is the
    // whole output (no result, no internal error from an allocation that failed).
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  }
}

TEST(Outputs, WarningsGoToStderrAndNameTheObjectAtOnce) {
  const fs::path dir = scratch("warn");
  luxgrid::test::write_file(dir / "p.json", R"({
    "format": "luxgrid-project/1", "name": "spacing in mm",
    "photometry": { "iso": { "builtin": "lambertian", "intensity_cd": 1000 } },
    "rooms": [ { "name": "r", "outline": [[0,0],[6,0],[6,4],[0,4]], "height": 3 } ],
    "luminaires": [ { "photometry": "iso", "position": [3, 2, 3] } ],
    "surfaces": [ { "name": "wp", "workplane": { "room": "r", "height": 0.8, "border": 0.5 }, "spacing": 250 } ]
  })");
  const std::string calc =
      std::string(LUXGRID_BINARY) + " calc " + quote(dir / "p.json") + " -o " + quote(dir / "out");
  const CommandResult stdout_only = luxgrid::test::shell("(" + calc + " 2>/dev/null)");
  ASSERT_EQ(stdout_only.code, 0) << stdout_only.output;
  EXPECT_EQ(stdout_only.output.find("warning"), std::string::npos) << stdout_only.output;
  const CommandResult both = luxgrid::test::shell(calc);
  const std::string w =
      "luxgrid: warning: p.json:6:106 /surfaces/0/spacing: the spacing 250 m of surface \"wp\" is "
      "larger than "
      "the surface (5 m x 3 m)";
  const auto at = both.output.find(w);
  ASSERT_NE(at, std::string::npos) << both.output;
  // Printed when the project is loaded, before the results.
  EXPECT_LT(at, both.output.find("results written to"));
  const auto j = nlohmann::json::parse(read_file(dir / "out/results.json"));
  ASSERT_EQ(j["warnings"].size(), 2u);  // the spacing, and the 1 x 1 grid it gave
  EXPECT_EQ("luxgrid: warning: " + j["warnings"][0].get<std::string>(),
            both.output.substr(at, both.output.find('\n', at) - at));
}

TEST(Outputs, InfoPrintsItsWarningsOnStderr) {
  const std::string file =
      (kSource / "tests/data/photometry/ldt/synthetic_isym3_c90c270.ldt").string();
  const std::string cmd = std::string(LUXGRID_BINARY) + " info " + quote(file);
  const CommandResult stdout_only = luxgrid::test::shell("(" + cmd + " 2>/dev/null)");
  ASSERT_EQ(stdout_only.code, 0);
  EXPECT_EQ(stdout_only.output.find("warning"), std::string::npos) << stdout_only.output;
  EXPECT_NE(stdout_only.output.find("flux"), std::string::npos);  // the summary itself is there
  const CommandResult stderr_only = luxgrid::test::shell("(" + cmd + " >/dev/null)");
  EXPECT_NE(
      stderr_only.output.find("luxgrid: warning: " + file + ": the C planes disagree at gamma 0"),
      std::string::npos)
      << stderr_only.output;
}

TEST(Outputs, PartPlotsOnlyWhenAskedAndKeptByARerunWithout) {
  // Reflected light runs (reflectances above 0): --part-plots adds each grid's direct and
  // reflected plots; a run without it writes the total's plot alone and keeps the earlier
  // run's part plots, saying so.
  const fs::path dir = scratch("part_plots");
  luxgrid::test::write_file(dir / "p.json", R"({
    "format": "luxgrid-project/1", "name": "parts",
    "photometry": { "iso": { "builtin": "lambertian", "intensity_cd": 1000 } },
    "rooms": [ { "name": "r", "outline": [[0,0],[4,0],[4,4],[0,4]], "height": 3,
                 "reflectance": { "floor": 0.2, "walls": 0.5, "ceiling": 0.7 } } ],
    "luminaires": [ { "photometry": "iso", "position": [2, 2, 3] } ],
    "surfaces": [ { "name": "floor", "workplane": { "room": "r", "height": 0, "border": 0 }, "spacing": 1 } ]
  })");
  const std::string calc = "calc " + quote(dir / "p.json") + " --quality draft --no-report -o ";
  ASSERT_EQ(luxgrid::test::luxgrid(calc + quote(dir / "plain")).code, 0);
  EXPECT_TRUE(fs::exists(dir / "plain/floor.png"));
  EXPECT_FALSE(fs::exists(dir / "plain/floor_direct.png"));
  EXPECT_FALSE(fs::exists(dir / "plain/floor_indirect.png"));
  ASSERT_EQ(luxgrid::test::luxgrid(calc + quote(dir / "parts") + " --part-plots").code, 0);
  const std::string direct = read_file(dir / "parts/floor_direct.png");
  EXPECT_FALSE(direct.empty());
  EXPECT_FALSE(read_file(dir / "parts/floor_indirect.png").empty());
  // The total's plot does not depend on whether the parts were drawn too.
  EXPECT_EQ(read_file(dir / "parts/floor.png"), read_file(dir / "plain/floor.png"));
  const CommandResult r = luxgrid::test::luxgrid(calc + quote(dir / "parts"));
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("floor_direct.png kept from the previous run (this run did not write "
                          "it: no --part-plots)"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(read_file(dir / "parts/floor_direct.png"), direct);
}

TEST(Outputs, ANoReportRerunKeepsTheEarlierReport) {
  const fs::path dir = scratch("rerun");
  luxgrid::test::write_file(dir / "p.json", R"({
    "format": "luxgrid-project/1", "name": "rerun",
    "photometry": { "iso": { "builtin": "lambertian", "intensity_cd": 1000 } },
    "rooms": [ { "name": "r", "outline": [[0,0],[4,0],[4,4],[0,4]], "height": 3,
                 "reflectance": { "floor": 0, "walls": 0, "ceiling": 0 } } ],
    "luminaires": [ { "photometry": "iso", "position": [2, 2, 3] } ],
    "surfaces": [ { "name": "floor", "workplane": { "room": "r", "height": 0, "border": 0 }, "spacing": 1 } ]
  })");
  const std::string calc =
      "calc " + quote(dir / "p.json") + " --quality draft -o " + quote(dir / "out");
  ASSERT_EQ(luxgrid::test::luxgrid(calc).code, 0);
  const std::string report = read_file(dir / "out/report.html");
  ASSERT_FALSE(report.empty());
  // The rerun without the report keeps the earlier one (and says so), writes the rest anew.
  const CommandResult r = luxgrid::test::luxgrid(calc + " --no-report");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("report.html kept from the previous run"), std::string::npos) << r.output;
  EXPECT_EQ(read_file(dir / "out/report.html"), report);
  // The kept file is luxgrid's again: listed in the marker, so a third run may replace it.
  EXPECT_NE(read_file(dir / "out/.luxgrid-output").find("\nreport.html\n"), std::string::npos);
  ASSERT_EQ(luxgrid::test::luxgrid(calc + " --no-report").code, 0);
  EXPECT_TRUE(fs::exists(dir / "out/report.html"));
  // The folder's safety rules still hold: a file luxgrid did not write refuses the folder, and
  // a link planted in place of the report is not followed nor kept.
  luxgrid::test::write_file(dir / "out/notes.txt", "mine");
  const CommandResult refused = luxgrid::test::luxgrid(calc + " --no-report");
  EXPECT_EQ(refused.code, 2) << refused.output;
  EXPECT_EQ(read_file(dir / "out/notes.txt"), "mine");
  fs::remove(dir / "out/notes.txt");
  luxgrid::test::write_file(dir / "secret.txt", "secret");
  fs::remove(dir / "out/report.html");
  fs::create_symlink(dir / "secret.txt", dir / "out/report.html");
  const CommandResult linked = luxgrid::test::luxgrid(calc + " --no-report");
  ASSERT_EQ(linked.code, 0) << linked.output;
  EXPECT_FALSE(fs::exists(fs::symlink_status(dir / "out/report.html")));
  EXPECT_EQ(read_file(dir / "secret.txt"), "secret");
}

TEST(Outputs, RepositoryDataIsFoundWhateverTheCurrentFolder) {
  // `validate` without CASES_DIR and `accuracy` without --photometry look their data up from the
  // binary, not the current folder (ctest's validate_cases runs `validate` that way end to end).
  const fs::path dir = scratch("elsewhere");
  const fs::path before = fs::current_path();
  fs::current_path(dir);
  const fs::path cases = luxgrid::cli::find_repository_path("cases");
  const fs::path ldt = luxgrid::cli::find_repository_path("tests/data/photometry/ldt");
  fs::current_path(before);
  EXPECT_TRUE(fs::equivalent(cases, kSource / "cases")) << cases;
  EXPECT_TRUE(fs::equivalent(ldt, kSource / "tests/data/photometry/ldt")) << ldt;
  // Nothing there: the name as given, so the error names what was looked for.
  EXPECT_EQ(luxgrid::cli::find_repository_path("no/such/folder"), fs::path("no/such/folder"));
}

TEST(Outputs, AccuracyTakesDashOAndFindsItsFilesFromAnyFolder) {
  const fs::path dir = scratch("accuracy");
  const CommandResult r = luxgrid::test::shell("cd " + quote(dir) + " && " + LUXGRID_BINARY +
                                               " accuracy --quick --grid 2 -o acc");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_GT(fs::file_size(dir / "acc/accuracy.md"), 100u);
  EXPECT_GT(fs::file_size(dir / "acc/accuracy.png"), 1000u);
}

}  // namespace

namespace {

TEST(Docs, ValidationListsEveryCaseAndProjectFormatEveryCsvColumn) {
  const std::string validation = read_file(kSource / "docs/validation.md");
  size_t cases = 0;
  for (const auto& e : fs::directory_iterator(kSource / "cases")) {
    if (!fs::exists(e.path() / "expected.json")) continue;
    ++cases;
    EXPECT_NE(validation.find("| `" + e.path().filename().string() + "` |"), std::string::npos)
        << e.path().filename() << " is not listed in docs/validation.md";
  }
  EXPECT_GE(cases, 22u);
  const std::string format = read_file(kSource / "docs/project-format.md");
  std::istringstream header(luxgrid::report::kSurfaceCsvHeader);
  std::string column;
  while (std::getline(header, column, ','))
    EXPECT_NE(format.find("`" + column + "`"), std::string::npos) << column << " is not documented";
}

}  // namespace
