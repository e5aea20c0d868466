// luxgrid diff: the relative point difference and the errors that name the surface.
#include <gtest/gtest.h>

#include "report/diff.h"
#include "util/error.h"

namespace luxgrid::report {
namespace {

nlohmann::json results(std::vector<std::pair<std::string, std::vector<double>>> surfaces) {
  nlohmann::json j = {{"format", "luxgrid-results/1"}, {"surfaces", nlohmann::json::array()}};
  for (auto& [name, e] : surfaces) {
    j["surfaces"].push_back(
        {{"name", name},
         {"E", e},
         {"stats", {{"Emin", 1}, {"Eavg", 2}, {"Emax", 3}, {"U0", 0.5}, {"Ud", 0.3}}}});
  }
  return j;
}

TEST(Diff, IdenticalResultsDifferByZero) {
  const auto a = results({{"wp", {100, 200, 300}}});
  const auto d = diff_results(a, "a", a, "b");
  ASSERT_EQ(d.surfaces.size(), 1u);
  EXPECT_EQ(d.surfaces[0].diff.max_rel, 0.0);
  EXPECT_EQ(d.surfaces[0].diff.mean_rel, 0.0);
  EXPECT_EQ(d.max_rel, 0.0);
}

TEST(Diff, PointsLeftOutCountNeitherWayAndBothFormatsAreRead) {
  // Format 2 marks left-out points; their E (0 in a real file, 7 here to show it is skipped) is
  // not compared, so the mean is over the two calculated points: (10 % + 0) / 2.
  auto a = results({{"wp", {110, 7, 200}}});
  auto b = results({{"wp", {100, 0, 200}}});
  a["format"] = b["format"] = "luxgrid-results/2";
  a["surfaces"][0]["active"] = b["surfaces"][0]["active"] = {true, false, true};
  const auto d = diff_results(a, "a", b, "b");
  EXPECT_EQ(d.surfaces[0].points, 2u);
  EXPECT_DOUBLE_EQ(d.surfaces[0].diff.max_rel, 0.1);
  EXPECT_DOUBLE_EQ(d.surfaces[0].diff.mean_rel, 0.05);
  // A format-1 file (no "active") against a format-2 one: the side that marks a point decides.
  a = results({{"wp", {110, 7, 200}}});
  EXPECT_EQ(diff_results(a, "a", b, "b").surfaces[0].points, 2u);
  // Two format-1 files: every point counts (7 against 0 is then a difference).
  b = results({{"wp", {100, 0, 200}}});
  EXPECT_EQ(diff_results(a, "a", b, "b").surfaces[0].points, 3u);
}

TEST(Diff, RelativeToTheReferenceWithAFloor) {
  // Points: 110 vs 100 -> 10 %; 200 vs 200 -> 0; 0.5 vs 0 -> |0.5| / (1 % of 200 = 2) = 25 %.
  const auto d = point_difference({110, 200, 0.5}, {100, 200, 0});
  EXPECT_DOUBLE_EQ(d.max_rel, 0.25);
  EXPECT_EQ(d.worst_index, 2u);
  EXPECT_DOUBLE_EQ(d.mean_rel, (0.1 + 0.0 + 0.25) / 3.0);
}

TEST(Diff, MatchesSurfacesByNameNotOrder) {
  const auto a = results({{"x", {1, 2}}, {"y", {10}}});
  const auto b = results({{"y", {10}}, {"x", {1, 2}}});
  const auto d = diff_results(a, "a", b, "b");
  EXPECT_EQ(d.max_rel, 0.0);
  EXPECT_EQ(d.surfaces[1].name, "y");
}

TEST(Diff, MissingSurfaceIsNamed) {
  const auto a = results({{"wp", {1}}, {"east wall", {1}}});
  const auto b = results({{"wp", {1}}});
  try {
    diff_results(a, "A.json", b, "B.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "B.json: surface \"east wall\" of A.json is missing");
  }
  try {
    diff_results(b, "B.json", a, "A.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "B.json: surface \"east wall\" of A.json is missing");
  }
}

TEST(Diff, DifferentPointCountsAreNamed) {
  try {
    diff_results(results({{"wp", {1, 2}}}), "A.json", results({{"wp", {1}}}), "B.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "surface \"wp\": A.json has 2 points, B.json has 1");
  }
}

TEST(Diff, NotAResultsFile) {
  EXPECT_THROW(diff_results(nlohmann::json::object(), "A.json", results({}), "B.json"), InputError);
}

}  // namespace
}  // namespace luxgrid::report
