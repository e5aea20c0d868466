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

TEST(Diff, PromiseMeasureLeavesThePointsAtOrBelowOnePercentOut) {
  // Largest B 200, so the floor is 2 lx. 101 vs 100: 1 %; 3 vs 1.5 (dark): 75 % on the floor's
  // measure, nothing on the promise's; 2.5 vs 2 (exactly at the floor, not brighter): left out.
  const std::vector<double> a{101, 200, 3.0, 2.5}, b{100, 200, 1.5, 2.0};
  const auto p = promise_error(a, b);
  EXPECT_DOUBLE_EQ(p.max_rel, 0.01);
  EXPECT_EQ(p.worst_index, 0u);
  EXPECT_EQ(p.bright_points, 2u);
  EXPECT_DOUBLE_EQ(point_difference(a, b).max_rel, 0.75);
  // Relative to B's own value, not A's: 90 against 100 is 10 %, 100 against 90 is 11.1 %.
  EXPECT_DOUBLE_EQ(promise_error({90, 200}, {100, 200}).max_rel, 0.1);
  EXPECT_DOUBLE_EQ(promise_error({100, 200}, {90, 200}).max_rel, 10.0 / 90.0);
}

TEST(Diff, PromiseWorstPointIsTheFilesPointWithItsPlace) {
  // The second point is left out (inactive): the worst of the others, 5 % at the file's third
  // point, is reported with its index in the file, its position and both values.
  auto a = results({{"wp", {100, 7, 105, 200}}});
  auto b = results({{"wp", {100, 0, 100, 200}}});
  a["format"] = b["format"] = "luxgrid-results/2";
  a["surfaces"][0]["active"] = b["surfaces"][0]["active"] = {true, false, true, true};
  a["surfaces"][0]["points"] = b["surfaces"][0]["points"] = {
      {0.5, 0.5, 0.8}, {1.5, 0.5, 0.8}, {2.5, 0.5, 0.8}, {3.5, 0.5, 0.8}};
  const auto d = diff_results(a, "a", b, "b");
  const auto& s = d.surfaces[0];
  EXPECT_DOUBLE_EQ(s.promise.max_rel, 0.05);
  EXPECT_EQ(s.promise.worst_index, 2u);
  EXPECT_EQ(s.promise.bright_points, 3u);
  EXPECT_DOUBLE_EQ(s.promise_a_lx, 105.0);
  EXPECT_DOUBLE_EQ(s.promise_b_lx, 100.0);
  ASSERT_TRUE(s.promise_point_m.has_value());
  EXPECT_DOUBLE_EQ((*s.promise_point_m)[0], 2.5);
  EXPECT_DOUBLE_EQ(d.promise_max_rel, 0.05);
  const std::string text = format_promise_diff(d);
  EXPECT_NE(text.find("wp                        3      3    5.000%       2  2.500, 0.500, 0.800"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("largest error: 5.000 %"), std::string::npos) << text;
}

TEST(Diff, PointsThatMovedAreBadInput) {
  // The same counts but a grid shifted by 1 mm: not the same points, whatever E says.
  auto a = results({{"wp", {100, 100}}});
  auto b = results({{"wp", {100, 100}}});
  a["surfaces"][0]["points"] = {{0.5, 0.5, 0.8}, {1.5, 0.5, 0.8}};
  b["surfaces"][0]["points"] = {{0.5, 0.5, 0.8}, {1.501, 0.5, 0.8}};
  try {
    diff_results(a, "A.json", b, "B.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "surface \"wp\": point 1 is at (1.5, 0.5, 0.8) m in A.json and at (1.501, 0.5, "
                 "0.8) m in B.json");
  }
  // Within 1e-6 m they are the same; a file without points (a reduced reference) is not checked.
  b["surfaces"][0]["points"][1][0] = 1.5 + 5e-7;
  EXPECT_NO_THROW(diff_results(a, "A.json", b, "B.json"));
  b["surfaces"][0].erase("points");
  EXPECT_NO_THROW(diff_results(a, "A.json", b, "B.json"));
}

TEST(Diff, NotAResultsFile) {
  EXPECT_THROW(diff_results(nlohmann::json::object(), "A.json", results({}), "B.json"), InputError);
}

}  // namespace
}  // namespace luxgrid::report
