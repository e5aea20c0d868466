// UGR_L: an upper limit on an observers surface's largest UGR, refused on other surfaces.
#include <gtest/gtest.h>

#include "report/requirement_checks.h"
#include "util/error.h"

namespace luxgrid::report {
namespace {

calc::Results observers_with_max(std::optional<double> ugr_max) {
  calc::Results r;
  calc::SurfaceResult s;
  s.grid.name = "eyes";
  s.grid.kind = geometry::SurfaceGrid::Kind::observers;
  s.UGR_max = ugr_max;
  r.surfaces.push_back(s);
  return r;
}

nlohmann::json project(double limit) {
  return {{"surfaces",
           {{{"name", "eyes"},
             {"observers", nlohmann::json::array()},
             {"requirements", {{"UGR_L", limit}}}}}}};
}

TEST(UgrRequirement, UpperLimitOnUgrMax) {
  const auto at =
      check_requirements(observers_with_max(19.0), parse_requirements(project(19), "p.json"));
  ASSERT_EQ(at.size(), 1u);
  EXPECT_EQ(at[0].quantity, "UGR_L");
  EXPECT_TRUE(at[0].upper_limit);
  EXPECT_TRUE(at[0].met);  // exactly at the limit
  const auto over =
      check_requirements(observers_with_max(19.4), parse_requirements(project(19), "p.json"));
  EXPECT_FALSE(over[0].met);
  EXPECT_NEAR(over[0].margin, -0.4, 1e-12);
  const auto under =
      check_requirements(observers_with_max(16.5), parse_requirements(project(19), "p.json"));
  EXPECT_TRUE(under[0].met);
  EXPECT_NEAR(under[0].margin, 2.5, 1e-12);
  EXPECT_NE(format_checks(under).find("required <= 19  achieved 16.5  met"), std::string::npos);
  // No luminaire in any view: nothing glares; met, achieved 0 (docs/glare.md).
  const auto none = check_requirements(observers_with_max(std::nullopt),
                                       parse_requirements(project(19), "p.json"));
  EXPECT_TRUE(none[0].met);
  EXPECT_EQ(none[0].achieved, 0.0);
}

TEST(UgrRequirement, OnATaskAreaWithoutObserversItIsNotCalculated) {
  // UGR_L on a task area reads the observers surfaces of the project; with none, the row is
  // shown as not calculated and is never counted as met.
  const nlohmann::json doc = {
      {"surfaces",
       {{{"name", "wp"}, {"workplane", {{"room", "r"}}}, {"requirements", {{"UGR_L", 19}}}}}}};
  calc::Results r;
  calc::SurfaceResult s;
  s.grid.name = "wp";
  r.surfaces.push_back(s);
  const auto checks = check_requirements(r, parse_requirements(doc, "p.json"));
  ASSERT_EQ(checks.size(), 1u);
  EXPECT_FALSE(checks[0].calculated);
  EXPECT_FALSE(checks[0].met);
  EXPECT_NE(checks[0].note.find("no observers surface"), std::string::npos) << checks[0].note;
  // With an observers surface beside it, the task area takes its largest UGR.
  calc::SurfaceResult eyes;
  eyes.grid.name = "eyes";
  eyes.grid.kind = geometry::SurfaceGrid::Kind::observers;
  eyes.UGR_max = 20.5;
  r.surfaces.push_back(eyes);
  const auto with = check_requirements(r, parse_requirements(doc, "p.json"));
  EXPECT_TRUE(with[0].calculated);
  EXPECT_FALSE(with[0].met);
  EXPECT_NEAR(with[0].achieved, 20.5, 1e-12);
}

}  // namespace
}  // namespace luxgrid::report
