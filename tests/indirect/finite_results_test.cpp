// run_scene never returns NaN or infinities (calc/pipeline.cpp, check_finite): a distribution of
// absurd candela values (near DBL_MAX, as a corrupt photometric file could give) must end in a
// CalculationError that names the surface and the first bad point or statistic.
#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "calc/pipeline.h"
#include "photometry/builtin.h"
#include "project/project_file.h"
#include "util/error.h"

namespace luxgrid::calc {
namespace {

// I = 1e308 cd everywhere (just below DBL_MAX = 1.8e308): E = I / d^2 overflows below 1 m.
class HugeDistribution final : public photometry::IntensityDistribution {
 public:
  double intensity(const Vec3&) const override { return 1e308; }
};

Scene huge_scene(const std::string& indirect) {
  const nlohmann::json doc = {
      {"format", "luxgrid-project/1"},
      {"name", "huge"},
      {"settings", {{"indirect", indirect}, {"near_field", "never"}}},
      {"photometry", {{"iso", {{"builtin", "isotropic"}, {"intensity_cd", 100}}}}},
      {"rooms", {{{"name", "box"}, {"outline", {{0, 0}, {4, 0}, {4, 4}, {0, 4}}}, {"height", 3}}}},
      {"luminaires", {{{"photometry", "iso"}, {"position", {2, 2, 2.5}}}}},
      {"surfaces",
       {{{"name", "probes"},
         {"points",
          {{{"at", {1, 1, 0.75}}, {"normal", {0, 0, 1}}},
           {{"at", {2, 2, 2.0}}, {"normal", {0, 0, 1}}},
           {{"at", {2.1, 2, 2.0}}, {"normal", {0, 0, 1}}}}}}}}};
  Scene s = project::parse_project(doc, "huge.json", ".").scene;
  s.luminaires[0].distribution = std::make_shared<HugeDistribution>();
  return s;
}

std::string error_of(const Scene& s) {
  try {
    run_scene(s);
  } catch (const CalculationError& e) {
    return e.what();
  }
  return "no error";
}

TEST(FiniteResults, AnOverflowingSumNamesTheSurfaceAndTheStatistic) {
  // Without indirect light every point value is finite (the direct calculation clamps +inf to
  // the largest double) but the mean of two such values overflows.
  const std::string m = error_of(huge_scene("off"));
  EXPECT_NE(m.find("surface 'probes': Eavg is inf"), std::string::npos) << m;
  EXPECT_NE(m.find("the results are not written"), std::string::npos) << m;
}

TEST(FiniteResults, ANonFinitePointIsNamedWithItsIndexAndPosition) {
  // Point 0 is 1.9 m from the source (E_direct ~3e307 lx, finite); point 1, 0.5 m below it,
  // gets the largest double as direct light, and that plus its reflected light overflows: the
  // first bad point, named by index and position.
  const std::string m = error_of(huge_scene("on"));
  EXPECT_NE(
      m.find("surface 'probes': the illuminance at point 1 (2, 2, 2) m is not a finite number "
             "(E_direct 1.798e+308 lx"),
      std::string::npos)
      << m;
}

TEST(FiniteResults, OrdinaryResultsPass) {
  Scene s = huge_scene("on");
  s.luminaires[0].distribution = std::make_shared<photometry::IsotropicDistribution>(100.0);
  EXPECT_NO_THROW(run_scene(s));
}

}  // namespace
}  // namespace luxgrid::calc
