// Openings as holes in the reflected light's patch mesh (calc/indirect/patches.h): no patch
// covers an opening, each patch's escape fraction is the form factor to the openings, and a
// luminaire's light reaching an opening leaves the room instead of being reflected by a ceiling
// or wall that is not there. Checked against the solid angle of a rectangle (closed form) and
// against the flux balance of the converged solve.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "calc/indirect/first_bounce.h"
#include "calc/indirect/form_factor.h"
#include "calc/indirect/indirect.h"
#include "calc/indirect/patches.h"
#include "photometry/builtin.h"
#include "tests/indirect/box_room.h"

namespace luxgrid::calc::indirect {
namespace {

// A 4 x 4 x 3 m box with a 1 x 1 m roof opening over its centre and a 2 x 1 m window in the wall
// along y = 0 (outline edge 0), at the reflectances given.
Scene holed_box(double rho) {
  Scene s;
  s.name = "holes";
  s.rooms = {box_room(4, 4, 3, rho, rho, rho)};
  DaylightOpening roof;
  roof.name = "roof";
  roof.polygon = {{1.5, 1.5, 3}, {2.5, 1.5, 3}, {2.5, 2.5, 3}, {1.5, 2.5, 3}};
  roof.face.kind = RoomFaceRef::Kind::ceiling;
  roof.inward_normal = {0, 0, -1};
  DaylightOpening window;
  window.name = "window";
  window.polygon = {{1, 0, 1}, {3, 0, 1}, {3, 0, 2}, {1, 0, 2}};
  window.face.kind = RoomFaceRef::Kind::wall;
  window.face.wall = 0;
  window.inward_normal = {0, 1, 0};
  s.openings = {roof, window};
  return s;
}

bool in_opening(const Vec3& c) {
  const bool roof = std::abs(c.z - 3) < 1e-9 && c.x > 1.5 && c.x < 2.5 && c.y > 1.5 && c.y < 2.5;
  const bool window = std::abs(c.y) < 1e-9 && c.x > 1 && c.x < 3 && c.z > 1 && c.z < 2;
  return roof || window;
}

// The patches tile the faces less the openings: their areas add up to the room's surface less
// 1 + 2 m^2 (to rounding, 1e-9 m^2), no patch's centroid lies in an opening, and each patch's
// escape fraction is Lambert's form factor from its centroid to the two openings.
TEST(OpeningHoles, PatchesLeaveTheOpeningsUncovered) {
  const Scene s = holed_box(0.5);
  const PatchMesh mesh = build_patch_mesh(s, 0.5);
  double area = 0.0;
  ASSERT_EQ(mesh.escape_fraction.size(), mesh.patches.size());
  for (size_t i = 0; i < mesh.patches.size(); ++i) {
    const Patch& p = mesh.patches[i];
    area += p.area_m2;
    EXPECT_FALSE(in_opening(p.centroid)) << i;
    const double f = point_polygon_form_factor(p.centroid, p.normal, s.openings[0].polygon) +
                     point_polygon_form_factor(p.centroid, p.normal, s.openings[1].polygon);
    EXPECT_NEAR(mesh.escape_fraction[i], f, 1e-15);
  }
  EXPECT_NEAR(area, room_surface_area(s.rooms[0]) - 3.0, 1e-9);
  // Without openings: no escape fractions, the closed room's whole area.
  Scene closed = s;
  closed.openings.clear();
  const PatchMesh whole = build_patch_mesh(closed, 0.5);
  EXPECT_TRUE(whole.escape_fraction.empty());
  double whole_area = 0.0;
  for (const Patch& p : whole.patches) whole_area += p.area_m2;
  EXPECT_NEAR(whole_area, room_surface_area(closed.rooms[0]), 1e-9);
}

// An isotropic source at (2, 2, 1.5): the light leaving through the roof opening is I x its solid
// angle, a centred rectangle of half sides a, b at distance d: Omega = 4 asin(a b / sqrt((a^2 +
// d^2)(b^2 + d^2))); through the window (half sides 1 and 0.5, centred 2 m in front, offset 0
// sideways and -0.0 in height: the source is at the window's mid-height 1.5) the same formula
// with d = 2. The first bounce's pieces carry exact solid angles, so the patches receive
// Phi (1 - (Omega_roof + Omega_window) / 4 pi) to rounding (1e-9 relative).
TEST(OpeningHoles, LuminaireLightLeavesThroughTheOpenings) {
  Scene s = holed_box(0.5);
  const double flux_lm = 1000.0;
  Luminaire l;
  l.label = "iso";
  l.pose.position = {2, 2, 1.5};
  l.distribution = std::make_shared<photometry::IsotropicDistribution>(flux_lm / (4.0 * kPi));
  s.luminaires = {l};
  const auto omega = [](double a, double b, double d) {
    return 4.0 * std::asin(a * b / std::sqrt((a * a + d * d) * (b * b + d * d)));
  };
  const double leaving = flux_lm * (omega(0.5, 0.5, 1.5) + omega(1.0, 0.5, 2.0)) / (4.0 * kPi);
  const PatchMesh mesh = build_patch_mesh(s, 0.5);
  const FirstBounce fb = first_bounce(s, mesh, {nullptr});
  EXPECT_NEAR(fb.received_flux_lm, flux_lm - leaving, 1e-9 * flux_lm);
  // The closed room keeps all of it.
  Scene closed = s;
  closed.openings.clear();
  const PatchMesh whole = build_patch_mesh(closed, 0.5);
  EXPECT_NEAR(first_bounce(closed, whole, {nullptr}).received_flux_lm, flux_lm, 1e-9 * flux_lm);
}

// The converged solve's balance in the holed room (rho 0.6): what lands on the surfaces straight
// from the luminaire = what they absorb, (1 - rho) / rho x the exitant flux (each patch's
// exitance is rho x all it receives), + what their reflected light sends out through the
// openings (IndirectResult::escaped_flux_lm). To the solve's tolerance at `standard` (1e-3 of
// the reflected flux) with a margin: 2e-3 of the flux received.
TEST(OpeningHoles, ConvergedSolveBalancesWithTheEscapingLight) {
  const double rho = 0.6;
  Scene s = holed_box(rho);
  Luminaire l;
  l.label = "iso";
  l.pose.position = {2, 2, 1.5};
  l.distribution = std::make_shared<photometry::IsotropicDistribution>(1000.0 / (4.0 * kPi));
  s.luminaires = {l};
  IndirectOptions o;
  o.quality = Quality::standard;
  const auto solution = solve_indirect(s, o);
  double exitant = 0.0;
  for (double f : solution->exitant_flux_lm) exitant += f;
  const double absorbed = (1.0 - rho) / rho * exitant;
  const double received = solution->result.received_flux_lm;
  EXPECT_GT(solution->result.escaped_flux_lm, 0.0);
  EXPECT_NEAR(absorbed + solution->result.escaped_flux_lm, received, 2e-3 * received);
}

}  // namespace
}  // namespace luxgrid::calc::indirect
