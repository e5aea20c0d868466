// The daylight scene's internally reflected component (calc/daylight_run.h, calc/daylight_light.h):
// the light entering through the openings as the first bounce of the reflected light, the
// openings holes in its mesh. Checked by the solve's flux balance, a black room, the integrating
// box (a closed box with a small opening, whose mean reflected illuminance follows from the
// balance alone) and a refined run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "calc/daylight_light.h"
#include "calc/daylight_run.h"
#include "calc/indirect/indirect.h"
#include "calc/pipeline.h"
#include "project/project_file.h"
#include "tests/calc/daylight_balance.h"

namespace luxgrid::calc {
namespace {

std::string irc_project(const std::string& size, const std::string& reflectance,
                        const std::string& sky, const std::string& openings,
                        const std::string& quality = "standard",
                        const std::string& spacing = "0.1") {
  return R"({"format": "luxgrid-project/1", "settings": {"scene": "daylight", "quality": ")" +
         quality + R"("},
    "rooms": [{"name": "r", "outline": )" +
         size + R"(, "height": 3, "reflectance": )" + reflectance + R"(}],
    "openings": )" +
         openings + R"(,
    "daylight": {"sky": {"type": )" +
         sky + R"(}, "ground": {"reflectance": 0.2}},
    "surfaces": [{"name": "room", "room_surfaces": {"room": "r"}, "spacing": )" +
         spacing + "}]}";
}

const std::string kFourByFour = "[[0,0],[4,0],[4,4],[0,4]]";
const std::string kColours = R"({"floor": 0.3, "walls": 0.6, "ceiling": 0.8})";
const std::string kGlazedWindow =
    R"([{"room": "r", "polygon": [[1,0,1],[3,0,1],[3,0,2.2],[1,0,2.2]],
         "glazing": {"transmittance": 0.8}}])";

Scene irc_scene(const std::string& text) {
  return project::parse_project_text(text, "d.json", ".").scene;
}

// The solve's balance, the window's flux by two independent integrations:
//  - the flux entering through the one window (its area times the transmitted illuminance just
//    inside it) and the flux landing on the patches (each patch's illuminance integrated at its
//    quarters) are the same light, since none can leave through another opening before it
//    lands: within 1 % (the patches' 2 x 2 midpoint rule near the window);
//  - what lands = what the surfaces absorb ((1 - rho) / rho x each patch's exitant flux) + what
//    their reflected light sends out through the window, to the converged solve's tolerance
//    (1e-3 at standard) with a margin: 2e-3.
TEST(DaylightIrc, SolveBalancesEnteringAbsorbedAndLeavingFlux) {
  const Scene s = irc_scene(irc_project(kFourByFour, kColours, "\"cie-overcast\"", kGlazedWindow));
  const DaylightLight light(s, nullptr, daylight_tolerance(Quality::standard));
  const auto solution = solve_with_first_bounce(
      s, [&light](const indirect::PatchMesh& m) { return light.patch_flux_lm(m); });
  const double entering = light.entering_flux_lm(0);
  const double landing = solution->result.received_flux_lm;
  EXPECT_GT(entering, 0.0);
  EXPECT_NEAR(landing, entering, 0.003 * entering);
  const double absorbed = absorbed_flux_lm(*solution);
  const double leaving = solution->result.escaped_flux_lm;
  EXPECT_GT(leaving, 0.0);
  EXPECT_NEAR(absorbed + leaving, landing, 2e-3 * landing);
}

// A black room reflects nothing: IRC is 0 at every point, exactly, whether the scene skips the
// reflected light (it does: no surface reflects) or the solve runs on the black faces.
TEST(DaylightIrc, BlackRoomHasNoInternallyReflectedComponent) {
  const std::string black = R"({"floor": 0, "walls": 0, "ceiling": 0})";
  const Scene s = irc_scene(irc_project(kFourByFour, black, "\"cie-overcast\"", kGlazedWindow));
  const Results r = run_scene(s);
  EXPECT_FALSE(r.plan.daylight->internally_reflected);
  for (const auto& sr : r.surfaces)
    for (size_t i = 0; i < sr.IRC.size(); ++i) {
      EXPECT_EQ(sr.IRC[i], 0.0);
      EXPECT_EQ(sr.DF[i], sr.SC[i] + sr.ERC[i]);
    }
  const DaylightLight light(s, nullptr, daylight_tolerance(Quality::standard));
  indirect::IndirectOptions o;
  o.incident_flux_lm = [&light](const indirect::PatchMesh& m) { return light.patch_flux_lm(m); };
  const auto solved = indirect::compute_indirect(s, s.surfaces, o);
  EXPECT_GT(solved.received_flux_lm, 0.0);
  for (const auto& values : solved.E_indirect_per_surface)
    for (double e : values) EXPECT_EQ(e, 0.0);
}

// The integrating box: a closed 3 m cube of reflectance rho = 0.5 under a 0.3 x 0.3 m unglazed
// roof opening takes in Phi = E_h x 0.09 m^2 (a horizontal opening lets in all the sky's light
// that crosses it, for any sky). Each reflection sends the share f of the reflected light out
// through the opening, so the exitant flux in all is B = rho Phi / (1 - rho (1 - f)) and the
// surfaces A_s receive B (1 - f) from reflections: a mean IRC of 100 B (1 - f) / (A_s E_h). In a
// sphere f = A_opening / A_total; in the cube f varies from patch to patch, but it is 1.7e-3, so
// its variation moves the mean by about rho x that, 1e-3. The mean over the faces is the 0.1 m
// grid's midpoint rule (the ceiling's points inside the opening left out). Tolerance 2 %: the
// first bounce's patch quadrature (the floor under the opening) and the gather's error near
// edges and corners (the quality's promise is 1 % per point).
TEST(DaylightIrc, IntegratingBoxMeanFollowsTheBalance) {
  const std::string cube = "[[0,0],[3,0],[3,3],[0,3]]";
  const std::string grey = R"({"floor": 0.5, "walls": 0.5, "ceiling": 0.5})";
  const std::string roof =
      R"([{"room": "r", "polygon": [[1.2,1.2,3],[1.5,1.2,3],[1.5,1.5,3],[1.2,1.5,3]]}])";
  const Results r = run_scene(irc_scene(irc_project(cube, grey, "\"uniform\"", roof)));
  ASSERT_TRUE(r.plan.daylight->internally_reflected);
  double sum = 0.0, area = 0.0;
  for (const auto& sr : r.surfaces) {
    const double cell = sr.grid.spacing_u * sr.grid.spacing_v;
    for (size_t i = 0; i < sr.IRC.size(); ++i) {
      const Vec3 p = sr.grid.points[i];
      if (p.z > 3 - 1e-9 && p.x > 1.2 && p.x < 1.5 && p.y > 1.2 && p.y < 1.5) continue;
      sum += sr.IRC[i] * cell, area += cell;
    }
  }
  EXPECT_NEAR(area, 54.0 - 0.09, 1e-9);
  const double rho = 0.5, a_open = 0.09, a_s = 54.0 - a_open, f = a_open / 54.0;
  const double expected = 100.0 * rho * a_open * (1 - f) / (a_s * (1 - rho * (1 - f)));
  EXPECT_NEAR(sum / area, expected, 0.02 * expected);
}

// The promise: DF at `standard` against a run at `high` (patches of half the size, the
// interreflection to 1e-4, the sky to 0.15 %) within standard's 1 % at every point, relative to
// the point's DF but no less than 1 % of its surface's largest (as `luxgrid cost` counts).
TEST(DaylightIrc, StandardHoldsItsPromiseAgainstHigh) {
  const Results std_run = run_scene(irc_scene(
      irc_project(kFourByFour, kColours, "\"cie-overcast\"", kGlazedWindow, "standard", "0.5")));
  const Results fine = run_scene(irc_scene(
      irc_project(kFourByFour, kColours, "\"cie-overcast\"", kGlazedWindow, "high", "0.5")));
  double worst = 0.0;
  for (size_t s = 0; s < fine.surfaces.size(); ++s) {
    const auto& a = std_run.surfaces[s];
    const auto& b = fine.surfaces[s];
    const double max_df = *std::max_element(b.DF.begin(), b.DF.end());
    for (size_t i = 0; i < b.DF.size(); ++i) {
      // Points in the window are left out (calc/points_in_openings.h): no surface there.
      if (!b.grid.active.empty() && !b.grid.active[i]) continue;
      const double e = std::abs(a.DF[i] - b.DF[i]) / std::max(b.DF[i], 0.01 * max_df);
      worst = std::max(worst, e);
      EXPECT_GT(b.IRC[i], 0.0);
    }
  }
  EXPECT_LE(worst, 0.01);
}

}  // namespace
}  // namespace luxgrid::calc
