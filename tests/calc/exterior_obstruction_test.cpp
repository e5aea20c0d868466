// Exterior obstructions in the daylight scene (calc/exterior_obstructions, calc/daylight_light):
// the ray query against hand-worked boxes; an obstruction hiding an opening's whole sky leaves
// SC = 0 and shows its face's luminance instead; a black obstruction lowers the sky component by
// exactly the sky it hides (a brute-force cubature over the opening); the faces' luminance against
// its closed forms under the uniform and the overcast sky.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "calc/daylight/sky_luminance.h"
#include "calc/daylight/sky_normalisation.h"
#include "calc/daylight_light.h"
#include "calc/exterior_obstructions.h"
#include "calc/pipeline.h"
#include "project/project_file.h"

namespace luxgrid::calc {
namespace {

const std::vector<ExteriorObstruction> kTwoBoxes = {{"near", {0, 0, 0}, {1, 1, 1}, 0.5},
                                                    {"far", {3, -1, -1}, {4, 2, 2}, 0.5}};

TEST(ExteriorObstructionQuery, FirstBoxAndItsFace) {
  // Along +x from (-1, 0.5, 0.5): the near box's -x face at 1, then the far box.
  auto hit = first_exterior_obstruction(kTwoBoxes, {-1, 0.5, 0.5}, {1, 0, 0});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->obstruction, 0u);
  EXPECT_EQ(hit->face, 0);
  EXPECT_DOUBLE_EQ(hit->distance_m, 1.0);
  // Above the near box: the far one, entered by its -x face at 5.
  hit = first_exterior_obstruction(kTwoBoxes, {-1, 0.5, 1.5}, {1, 0, 0});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->obstruction, 1u);
  EXPECT_DOUBLE_EQ(hit->distance_m, 4.0);
  // Down onto the near box's top (+z, face 5) from above, diagonally.
  const Vec3 d = glm::normalize(Vec3{0, 1, -1});
  hit = first_exterior_obstruction(kTwoBoxes, {0.5, -0.5, 2.0}, d);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->face, 5);
  EXPECT_NEAR(hit->distance_m, std::sqrt(2.0), 1e-15);
  EXPECT_EQ(box_face_normal(hit->face), Vec3(0, 0, 1));
  // Away from both, and grazing the near box's top face: nothing entered.
  EXPECT_FALSE(first_exterior_obstruction(kTwoBoxes, {-1, 0.5, 0.5}, {-1, 0, 0}));
  EXPECT_FALSE(first_exterior_obstruction(kTwoBoxes, {-1, 0.5, 1.0}, {0, 1, 0}));
  // From a point on the near box's +y face, outwards: nothing; inwards: the box at 0.
  EXPECT_FALSE(first_exterior_obstruction(kTwoBoxes, {0.5, 1.0, 0.5}, {0, 1, 0}));
  hit = first_exterior_obstruction(kTwoBoxes, {0.5, 1.0, 0.5}, {0, -1, 0});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->face, 3);
  EXPECT_EQ(hit->distance_m, 0.0);
}

std::string obstructed_project(const std::string& sky, const std::string& opening,
                               const std::string& obstructions,
                               const std::string& quality = "standard") {
  return R"({"format": "luxgrid-project/1",
    "settings": {"scene": "daylight", "quality": ")" +
         quality + R"("},
    "rooms": [{"name": "r", "outline": [[0,0],[4,0],[4,4],[0,4]], "height": 3,
               "reflectance": {"floor": 0, "walls": 0, "ceiling": 0}}],
    "openings": [{"room": "r", "polygon": )" +
         opening + R"(}],
    "daylight": {"sky": {"type": )" +
         sky + R"(}, "sun": {"altitude_deg": 60, "azimuth_deg": 180},
                 "ground": {"reflectance": 0.3}, "obstructions": )" +
         obstructions + R"(},
    "surfaces": [{"name": "p", "points": [{"at": [2, 2.5, 0], "normal": [0, 0, 1]},
                                          {"at": [1.2, 1.0, 0.5], "normal": [0, 0, 1]}]}]})";
}

Results run_obstructed(const std::string& text) {
  return run_scene(project::parse_project_text(text, "d.json", ".").scene);
}

const std::string kObstructedRoof = "[[1.5,1.5,3],[2.5,1.5,3],[2.5,2.5,3],[1.5,2.5,3]]";
const std::string kObstructedFacade = "[[1,0,1],[3,0,1],[3,0,2],[1,0,2]]";

// A slab lying on the roof over the whole opening: no sky at all, and in its place the slab's
// underside, which sees the ground's whole hemisphere: L = rho rho_g E_h / pi, a constant, so
// ERC = 100 rho rho_g / pi x the opening's projected solid angle (Lambert's formula), to
// rounding.
TEST(ExteriorObstructionDaylight, SlabOverRoofOpeningHidesAllSky) {
  for (const std::string sky : {"\"uniform\"", "\"cie-overcast\"", "12"}) {
    const std::string text =
        obstructed_project(sky, kObstructedRoof,
                           R"([{"box": {"min": [1,1,3], "max": [3,3,3.3]}, "reflectance": 0.5}])");
    const Results r = run_obstructed(text);
    // The plan says the obstruction is there, and no exact shortcut was taken.
    ASSERT_TRUE(r.plan.daylight);
    EXPECT_EQ(r.plan.daylight->exterior_obstructions, 1u);
    EXPECT_FALSE(r.plan.daylight->sky_exact);
    EXPECT_FALSE(r.plan.daylight->ground_exact);
    const Results open = run_obstructed(obstructed_project("\"uniform\"", kObstructedRoof, "[]"));
    for (int i = 0; i < 2; ++i) {
      EXPECT_EQ(r.surfaces[0].SC[i], 0.0) << sky;
      // The open roof's uniform-sky SC is 100 psa / pi: the slab's ERC is 0.5 x 0.3 of it.
      EXPECT_NEAR(r.surfaces[0].ERC[i], 0.5 * 0.3 * open.surfaces[0].SC[i],
                  1e-9 * open.surfaces[0].SC[i])
          << sky;
    }
  }
}

// The obstruction's light is the first bounce's too: under the uniform sky an open roof lets in a
// uniform luminance E_h / pi, the slab over it a uniform rho rho_g E_h / pi, so in a room that
// reflects, every point's internally reflected component is rho rho_g = 0.15 times the open
// roof's (the interreflection is linear in the light let in; the first bounce of either is exact,
// a constant over each triangle). Tolerance 1e-6: the solve's convergence.
TEST(ExteriorObstructionDaylight, SlabLightEntersTheInternallyReflectedComponent) {
  std::string slab =
      obstructed_project("\"uniform\"", kObstructedRoof,
                         R"([{"box": {"min": [1,1,3], "max": [3,3,3.3]}, "reflectance": 0.5}])");
  std::string open = obstructed_project("\"uniform\"", kObstructedRoof, "[]");
  for (std::string* text : {&slab, &open}) {
    const std::string black = R"("reflectance": {"floor": 0, "walls": 0, "ceiling": 0})";
    text->replace(text->find(black), black.size(),
                  R"("reflectance": {"floor": 0.2, "walls": 0.5, "ceiling": 0.7})");
  }
  const Results with = run_obstructed(slab), without = run_obstructed(open);
  for (int i = 0; i < 2; ++i) {
    EXPECT_GT(without.surfaces[0].IRC[i], 0.1);
    EXPECT_NEAR(with.surfaces[0].IRC[i], 0.15 * without.surfaces[0].IRC[i],
                1e-6 * without.surfaces[0].IRC[i]);
  }
}

// The sky a box hides from a point through the facade opening, by brute force: the midpoint rule
// on nx x nz cells over the opening, each node's ray tested against the box by where it crosses
// the plane of the face it must enter through (a fin east of the opening, x in [3, 3.3], y in
// [-2, 0], z in [0, 5]: a ray from the room reaches it through its west face x = 3 only).
double hidden_sky_percent(const daylight::SkyModel& sky, double sky_integral, const Vec3& p, int nx,
                          int nz) {
  double sum = 0.0;
  const double du = 2.0 / nx, dv = 1.0 / nz;
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < nz; ++j) {
      const Vec3 x{1.0 + (i + 0.5) * du, 0.0, 1.0 + (j + 0.5) * dv};
      const Vec3 d = x - p;
      if (!(d.x > 0.0)) continue;
      const double t = (3.0 - p.x) / d.x;  // the ray's parameter at x = 3
      const Vec3 at = p + t * d;
      if (!(at.y >= -2.0 && at.y <= 0.0 && at.z >= 0.0 && at.z <= 5.0)) continue;
      const double r = glm::length(d);
      const Vec3 w = d / r;
      sum += daylight::relative_luminance(sky, w) * w.z * (-w.y) / (r * r) * du * dv;
    }
  }
  return 100.0 * sum / sky_integral;
}

// Tolerance: from both points the fin's edge crosses the opening along a vertical line (what hides
// a ray does not depend on its height there), so the brute force's error is that of the one column
// of cells the edge cuts, at most half a cell (2.5e-4 m) of a hidden strip at least 0.44 m wide
// (3e-4 of the hidden sky), the smooth rest's at 100 cells in z about 1e-5; luxgrid's at
// `reference` is 1e-4 of each component. 1e-3 of the hidden sky holds both.
TEST(ExteriorObstructionDaylight, BlackFinLowersSkyByTheSkyItHides) {
  const std::string fin = R"([{"box": {"min": [3,-2,0], "max": [3.3,0,5]}, "reflectance": 0}])";
  for (const std::string sky : {"\"cie-overcast\"", "12"}) {
    const Results with =
        run_obstructed(obstructed_project(sky, kObstructedFacade, fin, "reference"));
    const Results without =
        run_obstructed(obstructed_project(sky, kObstructedFacade, "[]", "reference"));
    const auto parsed = project::parse_project_text(
        obstructed_project(sky, kObstructedFacade, "[]"), "d.json", ".");
    const daylight::SkyModel& model = parsed.scene.daylight->sky;
    const double I = daylight::horizontal_illuminance_per_zenith_luminance(model).value;
    for (int i = 0; i < 2; ++i) {
      const Vec3 p = with.surfaces[0].grid.points[i];
      const double hidden = hidden_sky_percent(model, I, p, 8000, 100);
      EXPECT_GT(hidden, 0.05 * without.surfaces[0].SC[i]) << "the fin hides a visible part";
      EXPECT_NEAR(without.surfaces[0].SC[i] - with.surfaces[0].SC[i], hidden, 1e-3 * hidden)
          << sky << " point " << i;
      EXPECT_EQ(with.surfaces[0].ERC[i], 0.0);  // black, and no ground in view from the floor
    }
  }
}

// A face's luminance over E_h: rho / pi x its illuminance from the sky and the ground. Under the
// uniform sky (L = E_h / pi) a vertical face receives E_h / 2 from the sky and rho_g E_h / 2 from
// the ground; under the traditional overcast sky (L = L_z (1 + 2 sin h) / 3, E_h = 7 pi L_z / 9)
// the sky's part is L_z (pi / 6 + 4 / 9) (the integral over the quarter sphere in front), so
// E_v / E_h = (3 / 14 + 4 / (7 pi)) + rho_g / 2; a face up receives E_h, a face down rho_g E_h.
TEST(ExteriorObstructionDaylight, FaceLuminanceClosedForms) {
  const std::string box = R"([{"box": {"min": [-5,-5,0], "max": [-4,-4,1]}, "reflectance": 0.4}])";
  for (const bool overcast : {false, true}) {
    const auto parsed = project::parse_project_text(
        obstructed_project(overcast ? "\"cie-overcast\"" : "\"uniform\"", kObstructedFacade, box),
        "d.json", ".");
    const DaylightLight light(parsed.scene, nullptr, 0.01);
    const double vertical = overcast ? 3.0 / 14.0 + 4.0 / (7.0 * kPi) : 0.5;
    const double rho = 0.4, rho_g = 0.3;
    for (int face = 0; face < 4; ++face)
      EXPECT_NEAR(light.face_luminance_per_eh(0, face), rho / kPi * (vertical + rho_g / 2.0), 1e-8);
    EXPECT_NEAR(light.face_luminance_per_eh(0, 4), rho / kPi * rho_g, 1e-8);
    EXPECT_NEAR(light.face_luminance_per_eh(0, 5), rho / kPi, 1e-8);
  }
}

}  // namespace
}  // namespace luxgrid::calc
