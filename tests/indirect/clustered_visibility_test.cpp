// The clustered transfer with visibility per link (calc/indirect/clustered.h) in an L-shaped room
// with a cabinet: against the dense matrix with its visibility on the same mesh, its factors'
// sums before the scale (light through the reflex corner's walls would push them above 1), the
// rooms that take it, and the split chosen before solving (split_mask.h, ambient_exitance).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "calc/indirect/clustered.h"
#include "calc/indirect/first_bounce.h"
#include "calc/indirect/limits.h"
#include "calc/indirect/patches.h"
#include "calc/indirect/radiosity.h"
#include "calc/indirect/split_mask.h"
#include "calc/scene_visibility.h"
#include "tests/indirect/box_room.h"
#include "tests/indirect/l_room.h"

namespace luxgrid::calc::indirect {
namespace {

struct LRoom {
  Scene scene = l_scene("clustered visibility");
  PatchMesh mesh;
  std::shared_ptr<const geometry::Visibility> visibility;
  explicit LRoom(double patch_size_m) : mesh(build_patch_mesh(scene, patch_size_m)) {
    VisibilityDecision decision;
    visibility = make_visibility(scene, decision);
  }
};

std::vector<double> reflectance_of(const PatchMesh& mesh) {
  std::vector<double> rho;
  for (const auto& p : mesh.patches) rho.push_back(p.reflectance);
  return rho;
}

// Same mesh (0.2 m: 2 317 patches, a third of them in the short leg and behind the cabinet),
// same visibility test: the dense matrix traces every partly hidden pair; the clustered operator
// proves whole nodes visible or hidden by their shafts and traces the pairs of single patches
// the rest. Where a node is taken whole, its point kernel errs as in an unobstructed room (a few
// times (opening / 2)^2, bound opening^2 / 2 of each patch's transferred light: the test
// Clustered.AgreesWithTheDenseMatrixWithinTheOpeningAnglesBound); where visibility were wrong
// (a hidden node linked, a visible one dropped), the patches of the short leg, lit only round
// the corner, would be off by tens of percent.
TEST(ClusteredVisibility, AgreesWithTheDenseMatrixWithItsVisibility) {
  const LRoom f(0.2);
  const double far_ratio = 5.0;  // standard
  const FirstBounce fb = first_bounce(f.scene, f.mesh, {f.visibility.get()});
  const std::vector<double> rho = reflectance_of(f.mesh);
  const FormFactorMatrix F = form_factors(f.mesh, 0, f.visibility.get(), far_ratio);
  const ClusteredTransfer T =
      clustered_transfer(f.mesh, 0, far_ratio, true, kMaxClusteredLinkBytes, f.visibility.get());
  const size_t n = f.mesh.patches.size();
  const RadiosityResult dense = solve_radiosity(F, rho, fb.incident_flux_lm, 0, 1e-9);
  const RadiosityResult clustered = solve_radiosity(T, rho, fb.incident_flux_lm, 0, 1e-9);
  const double bound = 0.5 * T.opening * T.opening;
  double worst = 0.0;
  size_t checked = 0;
  for (size_t i = 0; i < n; ++i) {
    const double first = rho[i] * fb.incident_flux_lm[i];
    const double carried = dense.exitant_flux_lm[i] - first;
    if (!(carried > 0.0)) continue;  // a patch that sees no lit patch at all
    ++checked;
    const double err = std::abs(clustered.exitant_flux_lm[i] - dense.exitant_flux_lm[i]) / carried;
    worst = std::max(worst, err);
    EXPECT_LE(err, bound) << "patch " << i;
  }
  EXPECT_GT(checked, n * 9 / 10);
  std::printf(
      "%zu patches, %zu links; worst difference in the transferred light %.3g %% (bound "
      "%.3g %%)\n",
      n, T.links(), 100 * worst, 100 * bound);
}

// Before the scale each source's factors sum to the share of its hemisphere the room's patches
// cover, 1 in a closed room, up to the kernels' errors (bounded by opening / 2 in an unobstructed
// box: Clustered.ConservesFluxInAClosedBox). A patch whose light were linked through a wall
// (a node behind the reflex corner taken as if nothing blocked) would sum to well above 1, by the
// share of its hemisphere the hidden faces take. Without visibility the same room exceeds the
// bound (checked below), so the test can fail.
TEST(ClusteredVisibility, FactorsSumToOneBeforeTheScaleOnlyWithVisibility) {
  const LRoom f(0.25);
  const ClusteredTransfer with =
      clustered_transfer(f.mesh, 0, 5.0, true, kMaxClusteredLinkBytes, f.visibility.get());
  const ClusteredTransfer without = clustered_transfer(f.mesh, 0, 5.0, true);
  std::printf("largest correction before the scale: %.3g with visibility, %.3g without\n",
              with.max_row_correction, without.max_row_correction);
  EXPECT_LT(with.max_row_correction, 0.5 * with.opening);
  EXPECT_GT(without.max_row_correction, 0.5 * without.opening);
  // After the scale a sweep neither creates nor loses light.
  std::vector<double> shot(with.n), received, work;
  for (size_t j = 0; j < with.n; ++j) shot[j] = 1.0 + std::sin(0.37 * static_cast<double>(j));
  apply_clustered(with, shot, received, work);
  double in = 0.0, out = 0.0;
  for (size_t j = 0; j < with.n; ++j) in += shot[j], out += received[j];
  EXPECT_NEAR(out / in, 1.0, 1e-12);
}

// Rooms where something blocks light take the clustered transfer once the dense matrix's pairs
// with rays would exceed the work the refinement allows (kClusteredVisibleAbovePatches); rooms
// where nothing blocks only beyond what a dense matrix can hold (kClusteredAbovePatches).
TEST(ClusteredVisibility, TakenByObstructedRoomsAboveTheirPatchCount) {
  const Room l = l_scene("which").rooms[0];  // 6 x 4 m less 3 x 2 m, 2.5 m high: 63 m^2 of faces
  const double area_m2 = room_surface_area(l);
  const auto size_for = [&](double patches) { return std::sqrt(area_m2 / patches); };
  EXPECT_FALSE(use_clustered_transfer(l, size_for(0.9 * kClusteredVisibleAbovePatches)));
  EXPECT_TRUE(use_clustered_transfer(l, size_for(1.1 * kClusteredVisibleAbovePatches)));
  const Room box = box_room(6, 4, 2.5, 0.3, 0.6, 0.7);
  const double box_m2 = room_surface_area(box);
  EXPECT_FALSE(
      use_clustered_transfer(box, std::sqrt(box_m2 / (1.1 * kClusteredVisibleAbovePatches))));
  EXPECT_TRUE(use_clustered_transfer(box, std::sqrt(box_m2 / (1.1 * kClusteredAbovePatches))));
}

// The ambient exitance of a closed room of uniform reflectance sums to the converged total of
// the bounce series, rho Phi / (1 - rho) for a first bounce Phi: the ambient term is exactly the
// light the later bounces add, spread evenly.
TEST(ClusteredVisibility, AmbientExitanceSumsToTheConvergedTotal) {
  const double rho = 0.6;
  Scene s;
  s.rooms = {box_room(5, 4, 3, rho, rho, rho)};
  const PatchMesh mesh = build_patch_mesh(s, 0.5);
  const size_t n = mesh.patches.size();
  std::vector<double> incident(n);
  double total_incident = 0.0;
  for (size_t i = 0; i < n; ++i) {
    incident[i] = 10.0 + 5.0 * std::cos(0.3 * static_cast<double>(i));
    total_incident += incident[i];
  }
  const std::vector<double> e = ambient_exitance(mesh, 0, n, incident);
  double total = 0.0;
  for (double x : e) total += x;
  EXPECT_NEAR(total / (rho * total_incident / (1.0 - rho)), 1.0, 1e-12);
  // Per patch: its own first bounce plus its share by area of the rest.
  const double ambient_lx = rho * total_incident / ((1.0 - rho) * room_surface_area(s.rooms[0]));
  for (size_t i = 0; i < n; i += 17)
    EXPECT_NEAR(e[i], rho * (incident[i] + mesh.patches[i].area_m2 * ambient_lx), 1e-9 * e[i]);
}

}  // namespace
}  // namespace luxgrid::calc::indirect
