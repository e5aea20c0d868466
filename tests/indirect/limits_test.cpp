// The limits of calc/indirect/limits.h: the per-room budget cannot be raised past the matrix
// limit, many rooms coarsen to the total patch limit (or, with an explicit size, are refused),
// and the solve ends at kMaxBounces even when the series never converges (reflectance 1).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "calc/indirect/indirect.h"
#include "calc/indirect/limits.h"
#include "calc/indirect/patches.h"
#include "calc/indirect/radiosity.h"
#include "photometry/builtin.h"
#include "util/error.h"

namespace luxgrid::calc::indirect {
namespace {

Room square_room(const std::string& name, double x0, double side, double rho) {
  Room r;
  r.name = name;
  r.outline = {{x0, 0}, {x0 + side, 0}, {x0 + side, side}, {x0, side}};
  r.height = 3.0;
  r.reflectance = {rho, rho, rho};
  return r;
}

// 60 rooms of 12 x 12 x 3 m: 432 m^2 each, 1 728 patches at 0.5 m, 103 680 in all: above
// kMaxTotalPatches though every room is within its own budget.
Scene many_rooms() {
  Scene s;
  for (int k = 0; k < 60; ++k)
    s.rooms.push_back(square_room("r" + std::to_string(k), 13.0 * k, 12.0, 0.5));
  return s;
}

TEST(Limits, ABudgetAboveTheMatrixLimitIsLowered) {
  Scene s;
  s.rooms = {square_room("box", 0, 4, 0.5)};
  IndirectOptions o;
  o.max_patches_per_room = 20000;
  const IndirectResult r = compute_indirect(s, {}, o);
  ASSERT_FALSE(r.notes.empty());
  // The budget of 20000 patches per room is above the limit of 10000 (a form-factor matrix of
  // 400 MB): 10000 used.
  EXPECT_EQ(r.notes[0].kind, IndirectNote::Kind::budget_above_limit);
  EXPECT_EQ(r.notes[0].asked, 20000u);
  EXPECT_EQ(r.notes[0].limit, 10000u);
  EXPECT_EQ(r.notes[0].matrix_mb, 400u);
}

TEST(Limits, TheSolverRefusesARoomAboveTheMatrixLimit) {
  // A mesh the budget never lets through (built directly): refused before 4 n^2 bytes are taken.
  Scene s;
  s.rooms = {square_room("box", 0, 30, 0.5)};
  const PatchMesh mesh = build_patch_mesh(s, 0.2);  // 30 x 30 x 3 m at 0.2 m: 54 000 patches
  ASSERT_GT(mesh.patches.size(), kMaxPatchesPerRoom);
  EXPECT_THROW(form_factors(mesh, 0, {}, 5.0), CalculationError);
}

TEST(Limits, ManyRoomsCoarsenToTheTotalPatchLimit) {
  const IndirectResult r = compute_indirect(many_rooms(), {}, IndirectOptions{});
  std::printf("%zu patches of %.3g m\n", r.patches, r.patch_size_m);
  for (const auto& n : r.notes) std::printf("note: %.3g m to %.3g m\n", n.from_m, n.to_m);
  EXPECT_LE(r.patches, kMaxTotalPatches);
  EXPECT_GT(r.patches, kMaxTotalPatches * 8 / 10);  // coarsened just enough, not to a few patches
  ASSERT_FALSE(r.notes.empty());
  // All 60 rooms: the patch size raised from 0.5 m to stay within 100000 patches in all rooms.
  EXPECT_EQ(r.notes[0].kind, IndirectNote::Kind::rooms_raised);
  EXPECT_EQ(r.notes[0].rooms, 60u);
  EXPECT_EQ(r.notes[0].from_m, 0.5);
  EXPECT_EQ(r.notes[0].limit, 100000u);
  EXPECT_FALSE(r.notes[0].clustered_limit);
}

TEST(Limits, AnExplicitPatchSizeOverTheTotalLimitIsRefused) {
  IndirectOptions o;
  o.patch_size_m = 0.5;
  try {
    compute_indirect(many_rooms(), {}, o);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "103680 patches in 60 rooms at a patch size of 0.5 m exceed the limit of 100000 "
              "patches in all rooms");
  }
}

TEST(Limits, TooManyBouncesAreRefusedByTheSolver) {
  FormFactorMatrix none;
  none.n = 1;
  EXPECT_THROW(solve_radiosity(none, {0.5}, {1.0}, kMaxBounces + 1, 1e-3), CalculationError);
  EXPECT_THROW(solve_radiosity(none, {0.5}, {1.0}, 0, 1e-3, kMaxBounces + 1), CalculationError);
}

TEST(Limits, AWhiteRoomStopsAtTheBounceLimit) {
  // Reflectance 1 everywhere: nothing is absorbed, the bounce series never converges, auto mode
  // stops at kMaxBounces and says so in its residual.
  Scene s;
  s.rooms = {square_room("white", 0, 4, 1.0)};
  Luminaire l;
  l.label = "iso";
  l.pose.position = {2, 2, 2};
  l.distribution = std::make_shared<photometry::IsotropicDistribution>(100.0);
  s.luminaires = {l};
  IndirectOptions o;
  o.patch_size_m = 1.0;
  const IndirectResult r = compute_indirect(s, {}, o);
  EXPECT_LE(r.bounces_run, kMaxBounces);
  EXPECT_GT(r.residual, 0.0) << r.bounces_run << " bounces";
}

}  // namespace
}  // namespace luxgrid::calc::indirect
