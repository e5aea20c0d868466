// A point luminaire in the wall two mirror-image rooms share (calc/indirect/emitter_cells.h): its
// light enters both rooms, half each (the isotropic source is symmetric about the wall), and the
// light is conserved: the direct flux landing on the faces of the closed rooms is the source's
// whole flux, and after every bounce the faces absorb it all.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "calc/indirect/emitter_cells.h"
#include "calc/indirect/first_bounce.h"
#include "calc/indirect/indirect.h"
#include "calc/indirect/patches.h"
#include "project/project_file.h"

namespace luxgrid::calc::indirect {
namespace {

constexpr double kI_cd = 1000.0;
// An isotropic source's flux: 4 pi I.
const double kFlux_lm = 4.0 * kPi * kI_cd;

// Rooms A = [0, 4] x [0, 4] and B = [4, 8] x [0, 4], 3 m high, the source at (4, 2, 1.5) in the
// wall x = 4 they share. Reflectances 0.5 everywhere, so every face absorbs as much as it
// reflects.
Scene shared_wall_scene() {
  auto room = [](const char* name, double x0) {
    return nlohmann::json{{"name", name},
                          {"outline", {{x0, 0}, {x0 + 4, 0}, {x0 + 4, 4}, {x0, 4}}},
                          {"height", 3.0},
                          {"reflectance", {{"floor", 0.5}, {"walls", 0.5}, {"ceiling", 0.5}}}};
  };
  nlohmann::json doc = {
      {"format", "luxgrid-project/1"},
      {"name", "shared wall"},
      {"photometry", {{"iso", {{"builtin", "isotropic"}, {"intensity_cd", kI_cd}}}}},
      {"rooms", {room("A", 0.0), room("B", 4.0)}},
      {"luminaires", {{{"photometry", "iso"}, {"position", {4.0, 2.0, 1.5}}}}},
      {"surfaces",
       {{{"name", "wp"}, {"workplane", {{"room", "A"}, {"height", 0.8}}}, {"spacing", 1.0}}}}};
  return project::parse_project(doc, "shared.json", ".").scene;
}

TEST(SharedWall, PointSourceEntersBothRoomsHalfEach) {
  const Scene scene = shared_wall_scene();
  const std::vector<RoomCells> parts = emitter_cells(scene, scene.luminaires.at(0));
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].room, 0);
  EXPECT_EQ(parts[1].room, 1);
  // Symmetric about the wall, and no quadrature direction lies in it: 1/2 to rounding.
  EXPECT_NEAR(parts[0].weight, 0.5, 1e-12);
  EXPECT_NEAR(parts[1].weight, 0.5, 1e-12);
  // Each room's cell carries the whole intensity: its patches see only the directions into it.
  EXPECT_EQ(parts[0].cells.at(0).weight, 1.0);
}

TEST(SharedWall, LightIsConservedInBothRooms) {
  const Scene scene = shared_wall_scene();
  IndirectOptions o;
  o.patch_size_m = 0.5;
  const auto solution = solve_indirect(scene, o);
  const IndirectResult& r = solution->result;
  // First bounce: the closed rooms catch every lumen (the solid angles of the patches around a
  // point tile the sphere exactly; 1e-9 is rounding).
  EXPECT_NEAR(r.emitted_flux_lm, kFlux_lm, 1e-9 * kFlux_lm);
  EXPECT_NEAR(r.received_flux_lm, kFlux_lm, 1e-9 * kFlux_lm);
  // After all bounces: a patch's exitance is rho x all it receives, so it absorbs
  // (1 - rho) / rho x its exitance; the faces of the closed rooms absorb the whole flux (measured
  // to 6e-16 relative: with one reflectance the sum is the solve's geometric series, which it
  // closes; 1e-9 leaves room for rounding).
  double absorbed = 0.0, exitant_a = 0.0, exitant_b = 0.0;
  const PatchMesh& mesh = solution->mesh;
  for (size_t i = 0; i < mesh.patches.size(); ++i) {
    const double rho = mesh.patches[i].reflectance;
    absorbed += (1.0 - rho) / rho * solution->exitant_flux_lm[i];
    (i < mesh.room_begin[1] ? exitant_a : exitant_b) += solution->exitant_flux_lm[i];
  }
  EXPECT_NEAR(absorbed, kFlux_lm, 1e-9 * kFlux_lm);
  // Mirror images: each room reflects the same light (1e-9: the meshes are mirror images).
  EXPECT_NEAR(exitant_a, exitant_b, 1e-9 * exitant_a);
}

}  // namespace
}  // namespace luxgrid::calc::indirect
