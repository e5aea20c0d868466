// Direct sunlight through openings (calc/daylight_sun.h, calc/daylight_run.cpp): the sun patch of
// a roof opening against its analytic projection, its flux against the flux entering, the
// glazing at the sun's angle, an obstacle's shadow, DF untouched by the sun, and the sun's
// reflected light's balance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "calc/daylight/clear_glass.h"
#include "calc/daylight_run.h"
#include "calc/daylight_sun.h"
#include "calc/indirect/indirect.h"
#include "calc/pipeline.h"
#include "calc/scene_visibility.h"
#include "project/project_file.h"
#include "tests/calc/daylight_balance.h"

namespace luxgrid::calc {
namespace {

constexpr double kSunDirectNormal_lx = 80000.0;

// A 4 x 4 x 3 m room, a 1 x 1 m glazed roof opening (x 2.5..3.5, y 1.5..2.5) with frame and
// maintenance factors, the sun at 60 degrees due east (azimuth 90: towards +x).
std::string sun_project(const std::string& reflectance, const std::string& obstacles,
                        const std::string& sun_extra, const std::string& surfaces) {
  return R"({"format": "luxgrid-project/1", "settings": {"scene": "daylight"},
    "rooms": [{"name": "r", "outline": [[0,0],[4,0],[4,4],[0,4]], "height": 3,
               "reflectance": )" +
         reflectance + R"(, "obstacles": )" + obstacles + R"(}],
    "openings": [{"name": "roof", "room": "r",
                  "polygon": [[2.5,1.5,3],[3.5,1.5,3],[3.5,2.5,3],[2.5,2.5,3]],
                  "glazing": {"transmittance": 0.8}, "frame_factor": 0.9,
                  "maintenance_factor": 0.95}],
    "daylight": {"sky": {"type": "cie-overcast"},
                 "sun": {"altitude_deg": 60, "azimuth_deg": 90)" +
         sun_extra + R"(}},
    "surfaces": )" +
         surfaces + "}";
}
const std::string kSunRoomBlack = R"({"floor": 0, "walls": 0, "ceiling": 0})";
const std::string kSunRoomColours = R"({"floor": 0.3, "walls": 0.6, "ceiling": 0.8})";
const std::string kSunOn = R"(, "direct_normal_lx": 80000)";
const std::string kSunWorkplane =
    R"([{"name": "plane", "workplane": {"room": "r", "height": 0.85}, "spacing": 0.25}])";

Scene load_sun_scene(const std::string& text) {
  return project::parse_project_text(text, "d.json", ".").scene;
}

// E_n x frame x maintenance x the glazing at the sun's incidence on the horizontal pane (its
// angle to the pane's normal is 30 degrees: cos = sin 60).
double sun_transmitted_lx() {
  const double sin_alt = std::sin(60.0 * kDegToRad);
  return kSunDirectNormal_lx * 0.9 * 0.95 * daylight::ClearGlass(0.8).transmittance(sin_alt);
}

// The floor's sun patch is the opening shifted by -3 m / tan 60 = -1.7320508 m along x (the
// roof lies 3 m above it): x in (0.7679492, 1.7679492), y in (1.5, 2.5). Inside, E = E_n x
// sin 60 x the factors x the glazing at the sun's angle (to 1e-12 relative); outside, 0. Points
// within 1e-9 m of the patch's edge are skipped (either answer is right there).
TEST(DaylightSun, RoofOpeningPatchIsTheOpeningProjectedAlongTheSun) {
  const Scene s = load_sun_scene(sun_project(kSunRoomBlack, "[]", kSunOn, kSunWorkplane));
  const DaylightSun sun(s, nullptr);
  const double shift = 3.0 / std::tan(60.0 * kDegToRad);
  const double x0 = 2.5 - shift, x1 = 3.5 - shift;
  const double inside_lx = sun_transmitted_lx() * std::sin(60.0 * kDegToRad);
  int lit = 0;
  for (int i = 0; i < 80; ++i)
    for (int j = 0; j < 80; ++j) {
      const double x = 0.025 + 0.05 * i, y = 0.025 + 0.05 * j;
      const double edge =
          std::min({std::abs(x - x0), std::abs(x - x1), std::abs(y - 1.5), std::abs(y - 2.5)});
      if (edge < 1e-9) continue;
      const bool in = x > x0 && x < x1 && y > 1.5 && y < 2.5;
      const double E = sun.at(Vec3(x, y, 0.0), Vec3(0, 0, 1));
      if (in) {
        ++lit;
        EXPECT_NEAR(E, inside_lx, 1e-12 * inside_lx) << x << " " << y;
      } else {
        EXPECT_EQ(E, 0.0) << x << " " << y;
      }
    }
  EXPECT_EQ(lit, 20 * 20);
  // A receiver facing away from the sun (normal -x, the sun towards +x) gets nothing, even
  // inside the patch.
  EXPECT_EQ(sun.at(Vec3(1.2, 2.0, 0.0), Vec3(-1, 0, 0)), 0.0);
}

// Flux conservation: the sum of E over a floor grid of 5 mm cells times the cell area equals the
// flux entering, E_n x A x cos(30 deg) x T(30 deg) x factors. The midpoint rule over the
// rectangle's cells is off by at most half a cell along each edge: 4 m x 2.5 mm / 1 m^2 = 1 %.
// DaylightSun::patch_flux_lm, the opening projected and clipped by each patch, gives the same
// flux over the mesh's patches to rounding (1e-9).
TEST(DaylightSun, FloorFluxEqualsFluxEntering) {
  const Scene s = load_sun_scene(sun_project(kSunRoomBlack, "[]", kSunOn, kSunWorkplane));
  const DaylightSun sun(s, nullptr);
  const double entering = kSunDirectNormal_lx * 1.0 * std::sin(60.0 * kDegToRad) *
                          daylight::ClearGlass(0.8).transmittance(std::sin(60.0 * kDegToRad)) *
                          0.9 * 0.95;
  EXPECT_NEAR(sun.entering_flux_lm(0), entering, 1e-12 * entering);
  const double h = 0.005;
  double sum = 0.0;
  for (int i = 0; i < 800; ++i)
    for (int j = 0; j < 800; ++j)
      sum += sun.at(Vec3((i + 0.5) * h, (j + 0.5) * h, 0.0), Vec3(0, 0, 1)) * h * h;
  EXPECT_NEAR(sum, entering, 0.01 * entering);
  for (const double patch_m : {0.5, 0.3}) {
    const indirect::PatchMesh mesh = indirect::build_patch_mesh(s, patch_m);
    const std::vector<double> flux = sun.patch_flux_lm(mesh);
    double total = 0.0;
    for (const double f : flux) total += f;
    EXPECT_NEAR(total, entering, 1e-9 * entering) << patch_m;
  }
}

// An obstacle (a 0.4 m cube on the floor under the patch) casts its shadow: a floor point behind
// it (on the line to the sun through the cube) gets no sun, one beside it in the patch the full
// value; the cube's top is lit.
TEST(DaylightSun, ObstacleCastsItsShadow) {
  const std::string box =
      R"([{"name": "box", "box": {"min": [1.1, 1.8, 0], "max": [1.5, 2.2, 0.4]},
           "reflectance": 0.5}])";
  const std::string probes = R"([{"name": "p", "points": [
      {"at": [1.05, 2.0, 0], "normal": [0, 0, 1]},
      {"at": [1.3, 1.6, 0], "normal": [0, 0, 1]},
      {"at": [1.3, 2.0, 0.4], "normal": [0, 0, 1]}]}])";
  const Results r = run_scene(load_sun_scene(sun_project(kSunRoomBlack, box, kSunOn, probes)));
  const std::vector<double>& E = r.surfaces[0].E_sun_direct;
  ASSERT_EQ(E.size(), 3u);
  const double inside_lx = sun_transmitted_lx() * std::sin(60.0 * kDegToRad);
  EXPECT_EQ(E[0], 0.0);  // (1.05, 2, 0) looks towards the sun through the box
  EXPECT_NEAR(E[1], inside_lx, 1e-12 * inside_lx);
  EXPECT_NEAR(E[2], inside_lx, 1e-12 * inside_lx);
}

// An exterior obstruction shades the sun as an obstacle does: a slab 0.5 m above the roof from
// x = 3 + 0.5 tan 30 deg on hides the sun rays leaving the opening's half x > 3 (they rise 0.5 m
// over 0.2887 m towards +x), so of the floor's patch x in (0.768, 1.768) only the part x < 1.268
// stays lit; a slab over the whole opening leaves no sun on any point or patch.
TEST(DaylightSun, ExteriorObstructionCastsItsShadow) {
  const double shift = 3.0 / std::tan(60.0 * kDegToRad);
  const double edge_x = 3.0 + 0.5 * std::tan(30.0 * kDegToRad);
  const auto with_slab = [&](double x0) {
    std::string text = sun_project(kSunRoomBlack, "[]", kSunOn, kSunWorkplane);
    const std::string slab = R"("obstructions": [{"name": "slab", "box": {"min": [)" +
                             std::to_string(x0) +
                             R"(, 1, 3.5], "max": [10, 3, 3.6]}, "reflectance": 0.2}], )";
    text.insert(text.find(R"("sun": {)"), slab);
    return load_sun_scene(text);
  };
  const double inside_lx = sun_transmitted_lx() * std::sin(60.0 * kDegToRad);
  {
    const Scene s = with_slab(edge_x);
    const DaylightSun sun(s, nullptr);
    // Floor points whose sun ray crosses the opening at x = 2.75 (lit) and x = 3.25 (hidden).
    EXPECT_NEAR(sun.at(Vec3(2.75 - shift, 2.0, 0.0), Vec3(0, 0, 1)), inside_lx, 1e-12 * inside_lx);
    EXPECT_EQ(sun.at(Vec3(3.25 - shift, 2.0, 0.0), Vec3(0, 0, 1)), 0.0);
  }
  {
    const Scene s = with_slab(2.0);
    const DaylightSun sun(s, nullptr);
    for (int i = 0; i < 40; ++i)
      EXPECT_EQ(sun.at(Vec3(0.05 + 0.1 * i, 2.0, 0.0), Vec3(0, 0, 1)), 0.0) << i;
    const indirect::PatchMesh mesh = indirect::build_patch_mesh(s, 0.5);
    for (const double f : sun.patch_flux_lm(mesh)) EXPECT_EQ(f, 0.0);
  }
}

// The daylight factor holds no sun: DF, SC, ERC and IRC are the same numbers with the sun on and
// off (exact equality), and E with the sun is E without it plus E_sun_direct and
// E_sun_reflected (to rounding).
TEST(DaylightSun, DaylightFactorUnchangedBySun) {
  const Results off =
      run_scene(load_sun_scene(sun_project(kSunRoomColours, "[]", "", kSunWorkplane)));
  const Results on =
      run_scene(load_sun_scene(sun_project(kSunRoomColours, "[]", kSunOn, kSunWorkplane)));
  ASSERT_EQ(off.surfaces.size(), on.surfaces.size());
  EXPECT_TRUE(off.surfaces[0].E_sun_direct.empty());
  EXPECT_TRUE(on.plan.daylight->direct_sun && on.plan.daylight->sun_reflected);
  for (std::size_t s = 0; s < on.surfaces.size(); ++s) {
    const SurfaceResult &a = off.surfaces[s], &b = on.surfaces[s];
    EXPECT_EQ(a.DF, b.DF);
    EXPECT_EQ(a.SC, b.SC);
    EXPECT_EQ(a.ERC, b.ERC);
    EXPECT_EQ(a.IRC, b.IRC);
    double sun_max = 0.0;
    for (std::size_t i = 0; i < b.E.size(); ++i) {
      const double sun = b.E_sun_direct[i] + b.E_sun_reflected[i];
      EXPECT_NEAR(b.E[i], a.E[i] + sun, 1e-9 * b.E[i]);
      EXPECT_GT(b.E_sun_reflected[i], 0.0);
      sun_max = std::max(sun_max, b.E_sun_direct[i]);
    }
    EXPECT_GT(sun_max, 0.0);
  }
}

// The sun's reflected light balances: the flux landing on the patches is the flux entering (to
// 1e-9, the projection being exact), and it equals what the surfaces absorb plus what their
// reflected light sends out through the opening, to the converged solve's tolerance (1e-3 at
// standard) with a margin: 2e-3 (as tests/calc/daylight_irc_test.cpp's balance).
TEST(DaylightSun, ReflectedSunBalancesEnteringAbsorbedAndLeavingFlux) {
  const Scene s = load_sun_scene(sun_project(kSunRoomColours, "[]", kSunOn, kSunWorkplane));
  const DaylightSun sun(s, nullptr);
  const auto solution = solve_with_first_bounce(
      s, [&sun](const indirect::PatchMesh& m) { return sun.patch_flux_lm(m); });
  const double entering = sun.entering_flux_lm(0);
  const double landing = solution->result.received_flux_lm;
  EXPECT_NEAR(landing, entering, 1e-9 * entering);
  const double absorbed = absorbed_flux_lm(*solution);
  const double leaving = solution->result.escaped_flux_lm;
  EXPECT_GT(leaving, 0.0);
  EXPECT_NEAR(absorbed + leaving, landing, 2e-3 * landing);
}

}  // namespace
}  // namespace luxgrid::calc
