// Identical inputs give byte-identical outputs: two runs of the example office write the same
// bytes into every file but timing.json (the phase times; the report's date follows
// SOURCE_DATE_EPOCH when it is set, the reproducible-builds convention).
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "tests/cli/cli_support.h"

// In cli_support.h's namespace, so its helpers need no using-declarations here.
namespace luxgrid::test {
namespace {

namespace fs = std::filesystem;

TEST(Reproducible, TwoRunsOfTheOfficeWriteIdenticalFiles) {
  const fs::path dir = scratch("office");
  const fs::path project = fs::path(LUXGRID_SOURCE_DIR) / "examples/office/project.json";
  for (const char* run : {"a", "b"}) {
    const auto r = luxgrid_at_fixed_date("calc " + quote(project) + " -o " + quote(dir / run));
    ASSERT_EQ(r.code, 0) << r.output;
  }
  const auto files = entries(dir / "a");
  ASSERT_EQ(files, entries(dir / "b"));
  EXPECT_TRUE(files.count("report.html") && files.count("results.json") &&
              files.count("timing.json"));
  for (const auto& f : files) {
    if (f == "timing.json") continue;
    EXPECT_TRUE(same_bytes(dir / "a" / f, dir / "b" / f)) << f;
  }
  // The date is the one given: 2025-12-01 00:00 UTC.
  EXPECT_NE(read_file(dir / "a" / "report.html").find("2025-12-01 00:00 UTC"), std::string::npos);
}

TEST(Reproducible, OneThreadAndTwoWriteIdenticalFiles) {
  // The outputs are written in parallel (each plot, CSV and the report's luminaire section a task
  // of its own; every thread keeps its own font cache): with one thread they are written one
  // after the other. Both must give the same bytes in every file but timing.json.
  const fs::path dir = scratch("office_threads");
  const fs::path project = fs::path(LUXGRID_SOURCE_DIR) / "examples/office/project.json";
  for (const char* threads : {"1", "2"}) {
    const auto r =
        luxgrid_at_fixed_date("--threads " + std::string(threads) + " calc " + quote(project) +
                              " --part-plots -o " + quote(dir / threads));
    ASSERT_EQ(r.code, 0) << r.output;
  }
  const auto files = entries(dir / "1");
  ASSERT_EQ(files, entries(dir / "2"));
  EXPECT_TRUE(files.count("report.html") && files.count("workplane_indirect.png"));
  for (const auto& f : files) {
    if (f == "timing.json") continue;
    EXPECT_TRUE(same_bytes(dir / "1" / f, dir / "2" / f)) << f;
  }
}

}  // namespace
}  // namespace luxgrid::test
