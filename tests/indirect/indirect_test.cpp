// Tests of calc/indirect: patch mesh, form factors, first bounce, radiosity, gather, decision.
// Each compares with something that could disagree: closed forms (Hottel's
// differential-area-to-rectangle factor, the integrating sphere), invariants (flux conservation,
// reciprocity) and an independent fine-patch solve.
#include <gtest/gtest.h>

#include "util/error.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>

#include "calc/direct.h"
#include "calc/indirect/first_bounce.h"
#include "calc/indirect/form_factor.h"
#include "calc/indirect/indirect.h"
#include "calc/indirect/patches.h"
#include "calc/indirect/radiosity.h"
#include "calc/indirect/subcells.h"
#include "calc/scaled_distribution.h"
#include "calc/scene_visibility.h"
#include "photometry/builtin.h"
#include "tests/indirect/box_room.h"

namespace luxgrid::calc::indirect {
namespace {

using geometry::SurfaceGrid;

// L-shape: 6 x 4 minus the 3 x 2 top-right corner (area 18 m^2).
Room l_room(double h, double rho) {
  Room r;
  r.name = "L";
  r.outline = {{0, 0}, {6, 0}, {6, 2}, {3, 2}, {3, 4}, {0, 4}};
  r.height = h;
  r.reflectance = {rho, rho, rho};
  return r;
}

Luminaire isotropic_at(const Vec3& p, double flux_lm) {
  Luminaire l;
  l.label = "iso";
  l.pose.position = p;
  l.distribution = std::make_shared<photometry::IsotropicDistribution>(flux_lm / (4.0 * kPi));
  return l;
}

Luminaire lambertian_at(const Vec3& p, double i0) {
  Luminaire l;
  l.label = "lambertian";
  l.pose.position = p;
  l.distribution = std::make_shared<photometry::LambertianDistribution>(i0);
  return l;
}

Scene scene_of(const Room& room, std::vector<Luminaire> lums) {
  Scene s;
  s.name = "test";
  s.rooms = {room};
  s.luminaires = std::move(lums);
  return s;
}

// Calculation grids covering every face of a box room (normals into the room).
std::vector<SurfaceGrid> box_face_grids(double w, double d, double h, double spacing) {
  using geometry::make_plane_grid;
  return {
      make_plane_grid("floor", {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, w, d, spacing),
      make_plane_grid("ceiling", {0, 0, h}, {0, 1, 0}, {1, 0, 0}, d, w, spacing),
      make_plane_grid("wall y0", {0, 0, 0}, {0, 0, 1}, {1, 0, 0}, h, w, spacing),
      make_plane_grid("wall x1", {w, 0, 0}, {0, 0, 1}, {0, 1, 0}, h, d, spacing),
      make_plane_grid("wall y1", {0, d, 0}, {1, 0, 0}, {0, 0, 1}, w, h, spacing),
      make_plane_grid("wall x0", {0, 0, 0}, {0, 1, 0}, {0, 0, 1}, d, h, spacing),
  };
}

double face_area(const SurfaceGrid& g) { return g.size_u * g.size_v; }

double mean(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

// Area-weighted mean over grids of the per-grid mean.
double area_weighted(const std::vector<SurfaceGrid>& grids,
                     const std::vector<std::vector<double>>& E) {
  double s = 0.0, a = 0.0;
  for (size_t k = 0; k < grids.size(); ++k) {
    s += mean(E[k]) * face_area(grids[k]);
    a += face_area(grids[k]);
  }
  return s / a;
}

// The scene's visibility test (the AABB tree of its room and obstacle faces), as the plan makes it.
std::shared_ptr<const geometry::OcclusionTree> tree_of(const Scene& s) {
  return std::make_shared<const geometry::OcclusionTree>(scene_faces(s));
}

// Patch-level indirect irradiance averaged over the whole room: indirect flux received / area.
struct PatchLevel {
  double direct_mean_lx, indirect_mean_lx;
};
PatchLevel patch_level(const Scene& scene, double size, int bounces) {
  const PatchMesh mesh = build_patch_mesh(scene, size);
  const auto tree = tree_of(scene);
  std::vector<const geometry::Visibility*> occ(scene.rooms.size(), nullptr);
  for (size_t r = 0; r < scene.rooms.size(); ++r)
    if (!outline_is_convex(scene.rooms[r])) occ[r] = tree.get();
  const FirstBounce fb = first_bounce(scene, mesh, occ);
  const FormFactorMatrix F = form_factors(mesh, 0, occ[0], 5.0);
  std::vector<double> rho;
  for (const auto& p : mesh.patches) rho.push_back(p.reflectance);
  const RadiosityResult sol = solve_radiosity(F, rho, fb.incident_flux_lm, bounces, 1e-6);
  // Indirect flux received by patch i = sum_j F[j->i] exitant_j.
  double area = 0.0, received = 0.0, direct = 0.0;
  for (size_t i = 0; i < F.n; ++i) {
    double s = 0.0;
    for (size_t j = 0; j < F.n; ++j) s += F.at(i, j) * sol.exitant_flux_lm[j];
    received += s;
    direct += fb.incident_flux_lm[i];
    area += mesh.patches[i].area_m2;
  }
  return {direct / area, received / area};
}

// ---------------------------------------------------------------------------------------------
// Patch mesh

TEST(PatchMesh, BoxTilesEveryFace) {
  const Scene s = scene_of(box_room(4, 3, 2.8, 0.2, 0.5, 0.7), {});
  const PatchMesh m = build_patch_mesh(s, 0.5);
  double area = 0.0;
  for (const auto& p : m.patches) {
    area += p.area_m2;
    EXPECT_NEAR(glm::length(p.normal), 1.0, 1e-12);
    // Normal points into the room: the room's centre is in front of every patch.
    EXPECT_GT(glm::dot(p.normal, Vec3(2, 1.5, 1.4) - p.centroid), 0.0);
    EXPECT_LE(p.diameter_m, 0.5 * std::sqrt(2.0) + 1e-9);
  }
  EXPECT_NEAR(area, room_surface_area(s.rooms[0]), 1e-9);
  EXPECT_NEAR(room_surface_area(s.rooms[0]), 2 * 12 + 14 * 2.8, 1e-12);
  EXPECT_EQ(m.patches.size(), 2u * 48 + 2u * (8 * 6) + 2u * (6 * 6));
}

TEST(PatchMesh, LShapeAndSlantedOutlineTileExactly) {
  Scene s = scene_of(l_room(3.0, 0.5), {});
  PatchMesh m = build_patch_mesh(s, 0.7);  // cells do not align with the re-entrant corner
  double floor = 0.0, total = 0.0;
  for (const auto& p : m.patches) {
    total += p.area_m2;
    if (p.face == FaceKind::floor) floor += p.area_m2;
  }
  EXPECT_NEAR(floor, 18.0, 1e-9);
  EXPECT_NEAR(total, room_surface_area(s.rooms[0]), 1e-9);
  EXPECT_FALSE(outline_is_convex(s.rooms[0]));

  // A pentagon with slanted edges.
  s.rooms[0].outline = {{0, 0}, {5, 0}, {6, 3}, {2.5, 5}, {-1, 3}};
  m = build_patch_mesh(s, 0.5);
  floor = 0.0;
  for (const auto& p : m.patches)
    if (p.face == FaceKind::floor) floor += p.area_m2;
  EXPECT_NEAR(floor, std::abs(geometry::signed_area(s.rooms[0].outline)), 1e-9);
}

TEST(PatchMesh, BadRoomsNameTheRoom) {
  Scene s = scene_of(box_room(4, 4, 3, 0.2, 1.5, 0.7), {});
  try {
    build_patch_mesh(s, 0.5);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "room 'box': reflectance of the walls is 1.500000, expected a number in [0, 1]");
  }
  s.rooms[0] = box_room(4, 4, 3, 0.2, 0.5, 0.7);
  s.rooms[0].outline.resize(2);
  EXPECT_THROW(build_patch_mesh(s, 0.5), InputError);
}

// ---------------------------------------------------------------------------------------------
// Form factors

// Differential area facing a parallel a x b rectangle whose corner is at the foot of the normal,
// distance c (Hottel; Howell's catalogue of configuration factors, B-3).
double hottel_corner(double a, double b, double c) {
  const double A = a / c, B = b / c;
  return (A / std::sqrt(1 + A * A) * std::atan(B / std::sqrt(1 + A * A)) +
          B / std::sqrt(1 + B * B) * std::atan(A / std::sqrt(1 + B * B))) /
         (2 * kPi);
}

TEST(FormFactor, LambertMatchesHottelForParallelRectangle) {
  const Polygon3 rect = {{0, 0, 2}, {3, 0, 2}, {3, 1.5, 2}, {0, 1.5, 2}};
  EXPECT_NEAR(point_polygon_form_factor({0, 0, 0}, {0, 0, 1}, rect), hottel_corner(3, 1.5, 2),
              1e-12);
  // Centre under the rectangle: four corner rectangles.
  EXPECT_NEAR(point_polygon_form_factor({1.5, 0.75, 0}, {0, 0, 1}, rect),
              4 * hottel_corner(1.5, 0.75, 2), 1e-12);
  // Very close: tends to 1, never above (no spike).
  EXPECT_NEAR(point_polygon_form_factor({1.5, 0.75, 2 - 1e-9}, {0, 0, 1}, rect), 1.0, 1e-6);
  // Behind the receiver: 0; half behind: the horizon clip halves the symmetric case.
  EXPECT_EQ(point_polygon_form_factor({1.5, 0.75, 0}, {0, 0, -1}, rect), 0.0);
  const Polygon3 wall = {{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}};
  const double full = point_polygon_form_factor({0, 0, 0}, {1, 0, 0}, wall);
  const Polygon3 upper = {{1, -1, 0}, {1, 1, 0}, {1, 1, 1}, {1, -1, 1}};
  EXPECT_NEAR(point_polygon_form_factor({0, 0, 0}, {0, 0, 1}, wall),
              point_polygon_form_factor({0, 0, 0}, {0, 0, 1}, upper), 1e-14);
  EXPECT_GT(point_polygon_form_factor({0, 0, 0}, {0, 0, 1}, upper), 0.0);
  EXPECT_GT(full, 0.0);
  // Point kernel: about (D/d)^2 / (2 pi) high on axis.
  const Polygon3 sq = {{-0.25, -0.25, 5}, {0.25, -0.25, 5}, {0.25, 0.25, 5}, {-0.25, 0.25, 5}};
  const double exact = point_polygon_form_factor({0, 0, 0}, {0, 0, 1}, sq);
  const double kernel = point_kernel_form_factor({0, 0, 0}, {0, 0, 1}, {0, 0, 5}, {0, 0, -1}, 0.25);
  const double D = 0.5 * std::sqrt(2.0);
  EXPECT_NEAR(kernel / exact - 1.0, (D / 5) * (D / 5) / (2 * kPi), 0.002);
}

// Tiny squares parallel to the receiver at 1 m, down to 2e-7 m across: every arc's sine is tiny
// (theta / sin -> 1 in Lambert's edges) and the factor down to 1e-14. On the axis the formula
// stays exact to a few units in the last place; off the axis the closed form is itself the
// difference of two corner rectangles, h(0.37 + a) - h(0.37 - a), which cancels: the allowance
// is a few units in the last place of those terms.
TEST(FormFactor, ATinyPatchStaysExactToRounding) {
  const double z = 1.0;
  for (double a : {1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) {
    for (double off : {0.0, 0.37}) {
      const Polygon3 sq = {{off - a, -a, z}, {off + a, -a, z}, {off + a, a, z}, {off - a, a, z}};
      const double got = point_polygon_form_factor({0, 0, 0}, {0, 0, 1}, sq);
      if (off == 0.0) {
        const double want = 4 * hottel_corner(a, a, z);
        EXPECT_NEAR(got, want, 4 * std::numeric_limits<double>::epsilon() * want) << a;
      } else {
        const double outer = 2 * hottel_corner(off + a, a, z),
                     inner = 2 * hottel_corner(off - a, a, z);
        EXPECT_NEAR(got, outer - inner,
                    16 * std::numeric_limits<double>::epsilon() * (outer + inner + got))
            << a;
      }
    }
  }
}

TEST(FormFactor, QuarterExtrapolationIsFarMoreAccurateThanThePointKernel) {
  // A 0.5 m square ceiling patch seen from receivers between 2.5 D and 5 D (the band where the
  // gather and the form factors use the quarters): level, tilted, off-axis, near the horizon.
  const Polygon3 sq = {{-0.25, -0.25, 0}, {0.25, -0.25, 0}, {0.25, 0.25, 0}, {-0.25, 0.25, 0}};
  const Vec3 m(0, 0, -1);
  const double D = 0.5 * std::sqrt(2.0), A = 0.25;
  const std::array<Vec3, 4> q = {Vec3(-0.125, -0.125, 0), Vec3(0.125, -0.125, 0),
                                 Vec3(0.125, 0.125, 0), Vec3(-0.125, 0.125, 0)};
  double worst_q = 0.0, worst_k = 0.0;
  int used = 0;
  for (double ratio : {2.6, 3.0, 4.0, 4.9})
    for (double az : {0.0, 0.3, 0.8, 1.2})
      for (const Vec3& n : {Vec3(0, 0, 1), glm::normalize(Vec3(1, 0, 1)), Vec3(-1, 0, 0)}) {
        const double d = ratio * D;
        const Vec3 x(d * std::sin(az), 0.0, -d * std::cos(az));
        const double exact = point_polygon_form_factor(x, n, sq);
        const double f = quarter_kernel_form_factor(x, n, sq, {0, 0, 0}, q, m, A, D, 0.0);
        if (f < 0.0) continue;  // straddles the horizon: the caller takes the exact formula
        ++used;
        const double k = point_kernel_form_factor(x, n, {0, 0, 0}, m, A);
        worst_q = std::max(worst_q, std::abs(f / exact - 1.0));
        worst_k = std::max(worst_k, std::abs(k / exact - 1.0));
      }
  std::printf("[ quarters ] 2.5-5 D: worst error %.2e (point kernel %.2e), %d cases\n", worst_q,
              worst_k, used);
  EXPECT_GT(used, 30);
  EXPECT_LT(worst_q, 2e-3);
  EXPECT_LT(worst_q, 0.1 * worst_k);
  // Too close for the quarters: -1 (exact formula).
  EXPECT_EQ(quarter_kernel_form_factor({0, 0, -1}, {0, 0, 1}, sq, {0, 0, 0}, q, m, A, D,
                                       std::pow(2.5 * D, 2)),
            -1.0);
}

TEST(FormFactor, RowsOfAClosedBoxSumToOne) {
  const Scene s = scene_of(box_room(4, 4, 3, 0.5, 0.5, 0.5), {});
  const PatchMesh m = build_patch_mesh(s, 0.5);
  const FormFactorMatrix exact =
      form_factors(m, 0, {}, std::numeric_limits<double>::infinity(), false);
  EXPECT_LT(exact.max_row_correction, 1e-6);  // exact polygon factors tile the hemisphere
  const FormFactorMatrix hybrid = form_factors(m, 0, {}, 5.0, false);
  std::printf("[ box 4x4x3, 0.5 m patches ] row-sum error: exact %.2e, hybrid (far ratio 5) %.2e\n",
              exact.max_row_correction, hybrid.max_row_correction);
  EXPECT_LT(hybrid.max_row_correction, 0.01);
}

// ---------------------------------------------------------------------------------------------
// First bounce

TEST(FirstBounce, ClosedRoomsReceiveTheWholeFlux) {
  for (const auto& room : {box_room(4, 4, 4, 0.5, 0.5, 0.5), l_room(3.0, 0.5)}) {
    for (int which = 0; which < 2; ++which) {
      const Vec3 pos = room.name == "box" ? Vec3(1.3, 2.2, 3.1) : Vec3(1.0, 1.0, 2.5);
      Luminaire lum = which == 0 ? isotropic_at(pos, 10000.0) : lambertian_at(pos, 1000.0);
      const Scene s = scene_of(room, {lum});
      const PatchMesh m = build_patch_mesh(s, 0.5);
      const auto tree = tree_of(s);
      std::vector<const geometry::Visibility*> occ(1, nullptr);
      if (!outline_is_convex(room)) occ[0] = tree.get();
      const FirstBounce fb = first_bounce(s, m, occ);
      const double emitted = luminous_flux(*lum.distribution);
      EXPECT_NEAR(fb.emitted_flux_lm, emitted, 1e-9 * emitted);
      std::printf("[ first bounce, %s, %s ] received %.3f lm of %.3f lm (%+.4f %%), %zu VPLs\n",
                  room.name.c_str(), which == 0 ? "isotropic" : "lambertian", fb.received_flux_lm,
                  emitted, 100 * (fb.received_flux_lm / emitted - 1), fb.vpl_count);
      // Exact solid angles tile the sphere: isotropic is exact up to visibility sampling in the L.
      EXPECT_NEAR(fb.received_flux_lm / emitted, 1.0, 0.005) << room.name << " " << which;
      if (which == 0 && room.name == "box") {
        EXPECT_NEAR(fb.received_flux_lm / emitted, 1.0, 1e-9);
      }
      double vpl = 0.0, rho_in = 0.0;
      for (size_t i = 0; i < m.patches.size(); ++i) {
        vpl += fb.vpl_flux_lm[i];
        rho_in += m.patches[i].reflectance * fb.incident_flux_lm[i];
      }
      EXPECT_NEAR(vpl, rho_in, 1e-9 * rho_in);
    }
  }
}

TEST(FirstBounce, PatchFluxMatchesDirectIlluminanceOnPatch) {
  // The patch flux divided by its area equals the mean far-field direct illuminance over it.
  const Luminaire lum = lambertian_at({1.3, 1.7, 2.9}, 1000.0);
  const Scene s = scene_of(box_room(4, 4, 3, 0.5, 0.5, 0.5), {lum});
  const PatchMesh m = build_patch_mesh(s, 0.5);
  const FirstBounce fb = first_bounce(s, m, {nullptr});
  double worst = 0.0;
  for (size_t i = 0; i < m.patches.size(); i += 7) {
    const Patch& p = m.patches[i];
    if (fb.incident_flux_lm[i] < 1.0) continue;
    // Patches reaching above the luminaire's horizon (z = 2.9) see the kink of I0 cos(gamma) at
    // gamma = 90 deg, where neither rule is second-order; they are checked by the flux total.
    bool above = false;
    for (const auto& v : p.polygon) above = above || v.z > 2.85;
    if (above) continue;
    // 40 x 40 midpoint rule over the (rectangular) patch.
    const Vec3 e1 = p.polygon[1] - p.polygon[0], e2 = p.polygon[3] - p.polygon[0];
    double e = 0.0;
    const int N = 40;
    for (int a = 0; a < N; ++a)
      for (int b = 0; b < N; ++b)
        e += far_field_illuminance(lum, p.polygon[0] + e1 * ((a + 0.5) / N) + e2 * ((b + 0.5) / N),
                                   p.normal);
    e /= N * N;
    worst = std::max(worst, std::abs(fb.incident_flux_lm[i] / p.area_m2 / e - 1.0));
  }
  std::printf("[ first bounce ] worst patch flux vs 40x40 midpoint direct: %.2e\n", worst);
  EXPECT_LT(worst, 2e-3);
}

// ---------------------------------------------------------------------------------------------
// Energy balance (docs/indirect.md): closed room of uniform rho; mean direct Phi/A, first bounce
// rho Phi/A, converged rho Phi/(A (1 - rho)); after N bounces rho Phi (1 - rho^N) / (A (1 - rho)).

TEST(EnergyBalance, BoxAndLRoomPerBounceCount) {
  const double flux = 10000.0;
  for (int shape = 0; shape < 2; ++shape) {
    for (double rho : {0.2, 0.5, 0.8}) {
      const Room room = shape == 0 ? box_room(4, 4, 3, rho, rho, rho) : l_room(3.0, rho);
      const Vec3 pos = shape == 0 ? Vec3(1.5, 2.5, 2.0) : Vec3(1.5, 1.0, 2.0);
      const Scene s = scene_of(room, {isotropic_at(pos, flux)});
      const double A = room_surface_area(room);
      for (int bounces : {1, 2, 3, 5, 10, 0}) {
        const PatchLevel pl = patch_level(s, 0.5, bounces);
        const double expect = bounces == 0
                                  ? rho * flux / (A * (1 - rho))
                                  : rho * flux * (1 - std::pow(rho, bounces)) / (A * (1 - rho));
        const double err = pl.indirect_mean_lx / expect - 1.0;
        std::printf(
            "[ energy %s rho %.1f bounces %-4s ] direct %.4f (err %+.1e)  indirect %.4f lx, "
            "expected %.4f, err %+.2e\n",
            shape == 0 ? "box" : "L  ", rho, bounces ? std::to_string(bounces).c_str() : "auto",
            pl.direct_mean_lx, pl.direct_mean_lx / (flux / A) - 1.0, pl.indirect_mean_lx, expect,
            err);
        EXPECT_NEAR(pl.direct_mean_lx / (flux / A), 1.0, shape == 0 ? 1e-9 : 5e-3);
        // Per bounce: exact in the box (rows sum to 1 and direct is exact); the L's error is
        // the direct flux's visibility-sampling error.
        EXPECT_NEAR(err, 0.0, shape == 0 ? 1e-5 : 5e-3);
      }
    }
  }
}

TEST(EnergyBalance, GatheredFaceAveragesInTheBox) {
  // The same balance through the final gather on calculation grids covering every face.
  const double flux = 10000.0;
  const auto grids = box_face_grids(4, 4, 3, 0.125);
  for (double rho : {0.2, 0.5, 0.8}) {
    const Scene s =
        scene_of(box_room(4, 4, 3, rho, rho, rho), {isotropic_at({1.5, 2.5, 2.0}, flux)});
    const double A = room_surface_area(s.rooms[0]);
    for (int bounces : {1, 0}) {
      IndirectOptions o;
      o.bounces = bounces;
      const IndirectResult r = compute_indirect(s, grids, o);
      const double expect = bounces == 1 ? rho * flux / A : rho * flux / (A * (1 - rho));
      const double got = area_weighted(grids, r.E_indirect_per_surface);
      std::printf("[ gather box rho %.1f %s ] %.4f lx vs %.4f (%+.3f %%); %zu patches\n", rho,
                  bounces ? "1 bounce" : "auto    ", got, expect, 100 * (got / expect - 1),
                  r.patches);
      EXPECT_NEAR(got / expect, 1.0, 0.005);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// CIE 171:2006 case 5.8: 4 x 4 x 4 m closed room, isotropic 10 000 lm at the centre, uniform rho;
// face-averaged indirect illuminance rho Phi / (S_T (1 - rho)), S_T = 96 m^2. Hold within 1 %.
// The case folders cases/cie171_5_8_* describe the same room; `luxgrid validate` (the ctest
// validate_cases) checks them end to end against their expected.json, so they are not run here.

TEST(Cie171Case58, FaceAveragedIndirectAtEveryRho) {
  const auto grids = box_face_grids(4, 4, 4, 0.25);
  std::printf(
      "[ CIE 171 5.8 ]   rho   expected lx   floor lx   wall lx   ceiling lx   worst err   "
      "bounces  time s\n");
  for (double rho : {0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95}) {
    const Scene s = scene_of(box_room(4, 4, 4, rho, rho, rho), {isotropic_at({2, 2, 2}, 10000.0)});
    const double expect = rho * 10000.0 / (96.0 * (1 - rho));
    const IndirectResult r = compute_indirect(s, grids, IndirectOptions{});
    double worst = 0.0;
    for (const auto& e : r.E_indirect_per_surface)
      worst = std::max(worst, std::abs(mean(e) / expect - 1));
    std::printf("[ CIE 171 5.8 ]  %.2f  %10.3f  %9.3f  %8.3f  %10.3f  %+9.2e  %4d%s  %.2f\n", rho,
                expect, mean(r.E_indirect_per_surface[0]), mean(r.E_indirect_per_surface[2]),
                mean(r.E_indirect_per_surface[1]), worst, r.bounces_run, r.tail_added ? "+t" : "  ",
                r.seconds);
    EXPECT_LT(worst, 0.01) << "rho " << rho;
  }
}

// ---------------------------------------------------------------------------------------------
// Gather: continuous up to walls and corners, and across the near/far switch.

TEST(Gather, NoSpikesNearWallsAndCorners) {
  const Scene s = scene_of(box_room(4, 4, 3, 0.5, 0.5, 0.7), {isotropic_at({2, 2, 2.5}, 10000.0)});
  // Points on the floor approaching the corner (0, 0) along the diagonal, down to 0.
  SurfaceGrid g;
  g.name = "diagonal";
  g.kind = SurfaceGrid::Kind::points;
  for (double t : {0.5, 0.25, 0.1, 0.05, 0.02, 0.01, 1e-3, 1e-4, 0.0}) {
    g.points.push_back({t, t, 0.0});
    g.normals.push_back({0, 0, 1});
  }
  g.active.assign(g.points.size(), true);
  g.nu = static_cast<int>(g.points.size());
  g.nv = 1;
  const IndirectResult r = compute_indirect(s, {g}, IndirectOptions{});
  const auto& E = r.E_indirect_per_surface[0];
  for (size_t i = 0; i < E.size(); ++i) {
    EXPECT_TRUE(std::isfinite(E[i]));
    EXPECT_GT(E[i], 0.0);
    if (i > 0) {
      EXPECT_LE(E[i], E[i - 1] * 1.02) << "spike at " << g.points[i].x;  // corners are darker
      EXPECT_GE(E[i], E[i - 1] * 0.7) << "hole at " << g.points[i].x;
    }
  }
  std::printf("[ gather corner ] E_indirect from 0.5 m to the corner:");
  for (double e : E) std::printf(" %.2f", e);
  std::printf("\n");
}

TEST(Gather, AGridFacingOutOfTheRoomGetsNothingFromIt) {
  // A grid on a face of a room whose normal points out of the room lies on the face's outer side:
  // the opaque face hides the room, so its reflected light is exactly 0 (its direct light is 0
  // too). The same grid facing in still reads the CIE 171 case 5.8 value (uniform exitance in a
  // closed box: rho Phi / (S_T (1 - rho)), within the 1 % that case holds).
  const double rho = 0.5;
  const Scene s = scene_of(box_room(4, 4, 4, rho, rho, rho), {isotropic_at({2, 2, 2}, 10000.0)});
  std::vector<SurfaceGrid> grids = box_face_grids(4, 4, 4, 0.5);
  const size_t faces = grids.size();
  for (size_t k = 0; k < faces; ++k) {
    SurfaceGrid out = grids[k];
    out.name += " facing out";
    for (auto& n : out.normals) n = -n;
    grids.push_back(out);
  }
  const IndirectResult r = compute_indirect(s, grids, IndirectOptions{});
  const double expect = rho * 10000.0 / (96.0 * (1 - rho));
  for (size_t k = 0; k < faces; ++k) {
    EXPECT_NEAR(mean(r.E_indirect_per_surface[k]) / expect, 1.0, 0.01) << grids[k].name;
    for (double e : r.E_indirect_per_surface[faces + k]) EXPECT_EQ(e, 0.0) << grids[faces + k].name;
  }
}

TEST(Gather, ContinuousAcrossTheNearFarSwitch) {
  // Exact everywhere vs the hybrid: at standard quality (far ratio 5) the difference per point is
  // bounded by the point kernel's error on the far patches.
  const Scene s = scene_of(box_room(6, 5, 3, 0.3, 0.6, 0.8), {isotropic_at({2, 2, 2.5}, 10000.0)});
  const auto grids = box_face_grids(6, 5, 3, 0.2);
  IndirectOptions exact;
  exact.far_ratio = std::numeric_limits<double>::infinity();
  const IndirectResult a = compute_indirect(s, grids, exact);
  const IndirectResult b = compute_indirect(s, grids, IndirectOptions{});
  double worst = 0.0;
  for (size_t k = 0; k < grids.size(); ++k)
    for (size_t i = 0; i < grids[k].points.size(); ++i)
      worst = std::max(
          worst, std::abs(b.E_indirect_per_surface[k][i] / a.E_indirect_per_surface[k][i] - 1));
  std::printf(
      "[ gather switch ] hybrid (far ratio 5) vs exact: worst point %.3f %%; time %.2f s vs %.2f "
      "s\n",
      100 * worst, b.seconds, a.seconds);
  EXPECT_LT(worst, 0.01);
}

// ---------------------------------------------------------------------------------------------
// Non-uniform reflectance vs an independent fine-patch solve: 0.25 m patches, emitter-averaged
// form factors (3 x 3 sub-points per emitting patch, exact polygon factor to each receiver, no
// renormalisation), direct flux from the far-field illuminance at 4 x 4 points per patch, and a
// direct dense LU solve of (I - diag(rho) F^T) Phi = rho D.

std::vector<double> lu_solve(std::vector<double> A, std::vector<double> b, size_t n) {
  for (size_t k = 0; k < n; ++k) {
    size_t piv = k;
    for (size_t i = k + 1; i < n; ++i)
      if (std::abs(A[i * n + k]) > std::abs(A[piv * n + k])) piv = i;
    if (piv != k) {
      for (size_t j = 0; j < n; ++j) std::swap(A[k * n + j], A[piv * n + j]);
      std::swap(b[k], b[piv]);
    }
    for (size_t i = k + 1; i < n; ++i) {
      const double f = A[i * n + k] / A[k * n + k];
      if (f == 0.0) continue;
      for (size_t j = k; j < n; ++j) A[i * n + j] -= f * A[k * n + j];
      b[i] -= f * b[k];
    }
  }
  for (size_t k = n; k-- > 0;) {
    double s = b[k];
    for (size_t j = k + 1; j < n; ++j) s -= A[k * n + j] * b[j];
    b[k] = s / A[k * n + k];
  }
  return b;
}

TEST(NonUniformReflectance, AgreesWithIndependentFinePatchSolve) {
  const Room room = box_room(4, 4, 3, 0.2, 0.5, 0.8);
  const Scene s = scene_of(
      room, {isotropic_at({2.2, 1.8, 2.4}, 6000.0), lambertian_at({1.0, 3.0, 2.95}, 800.0)});
  // Reference.
  const PatchMesh m = build_patch_mesh(s, 0.25);
  const size_t n = m.patches.size();
  std::vector<double> D(n, 0.0);
  for (size_t i = 0; i < n; ++i) {
    const Patch& p = m.patches[i];
    const Vec3 e1 = p.polygon[1] - p.polygon[0], e2 = p.polygon[3] - p.polygon[0];
    double e = 0.0;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (const auto& lum : s.luminaires)
          e += far_field_illuminance(
              lum, p.polygon[0] + e1 * ((a + 0.5) / 4) + e2 * ((b + 0.5) / 4), p.normal);
    D[i] = e / 16 * p.area_m2;
  }
  std::vector<double> M(n * n, 0.0);  // M[i][j] = delta_ij - rho_i F[j->i]
  for (size_t j = 0; j < n; ++j) {
    const Patch& src = m.patches[j];
    const Vec3 e1 = src.polygon[1] - src.polygon[0], e2 = src.polygon[3] - src.polygon[0];
    for (size_t i = 0; i < n; ++i) {
      if (i == j) continue;
      const Patch& dst = m.patches[i];
      double f = 0.0;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          f += point_polygon_form_factor(
              src.polygon[0] + e1 * ((a + 0.5) / 3) + e2 * ((b + 0.5) / 3), src.normal,
              dst.polygon);
      M[i * n + j] = -dst.reflectance * f / 9;
    }
    M[j * n + j] = 1.0;
  }
  std::vector<double> rhs(n);
  for (size_t i = 0; i < n; ++i) rhs[i] = m.patches[i].reflectance * D[i];
  const std::vector<double> phi = lu_solve(M, rhs, n);
  // Reference face averages of indirect irradiance: (exitant / rho - direct) / area.
  double ref[3] = {0, 0, 0}, area[3] = {0, 0, 0};
  for (size_t i = 0; i < n; ++i) {
    const int f = static_cast<int>(m.patches[i].face);
    ref[f] += phi[i] / m.patches[i].reflectance - D[i];
    area[f] += m.patches[i].area_m2;
  }
  // luxgrid at standard quality, gathered on face grids.
  const auto grids = box_face_grids(4, 4, 3, 0.2);
  const IndirectResult r = compute_indirect(s, grids, IndirectOptions{});
  const double got_floor = mean(r.E_indirect_per_surface[0]);
  const double got_ceiling = mean(r.E_indirect_per_surface[1]);
  double walls = 0.0, wall_area = 0.0;
  for (size_t k = 2; k < 6; ++k) {
    walls += mean(r.E_indirect_per_surface[k]) * face_area(grids[k]);
    wall_area += face_area(grids[k]);
  }
  walls /= wall_area;
  const double want[3] = {ref[0] / area[0], ref[1] / area[1], ref[2] / area[2]};
  const double got[3] = {got_floor, got_ceiling, walls};
  const char* names[3] = {"floor", "ceiling", "walls"};
  for (int f = 0; f < 3; ++f) {
    std::printf(
        "[ non-uniform 0.2/0.5/0.8 ] %-7s luxgrid %.3f lx, fine LU reference %.3f lx (%+.2f %%)\n",
        names[f], got[f], want[f], 100 * (got[f] / want[f] - 1));
    EXPECT_NEAR(got[f] / want[f], 1.0, 0.01) << names[f];
  }
  std::printf("[ non-uniform ] reference %zu patches; luxgrid: %zu\n", n, r.patches);
}

// Points near a corner see mostly the nearest part of the adjacent face's patches, where the
// exitance differs from the patch's mean; patches seen from closer than a diameter are therefore
// gathered cell by cell (subcells.h). An office-like box (downlights under the ceiling leave the
// tops of the walls and the ceiling's corners dark), face grids at 0.25 m spacing (points
// 0.125 m from every edge, as in examples/office), standard's 0.5 m patches against a converged
// 0.15 m mesh, in the promise's measure (below). Luminaires 0.1 m under the ceiling make the
// corners darker than the office's: without cells they are 10 % off (examples/office: 4.1 %); with
// them the corners' error falls below the rest of the mesh's (measured: 1.9 % where the ceiling
// as a whole reads 1 % low at 0.5 m patches, 10.5 % without cells). Tolerances: 2.5 % with cells
// (the 1.9 % measured plus margin), above 5 % without, so the test sees the effect it guards.
TEST(Gather, CellsNearCornersMeetTheStandardPromise) {
  std::vector<Luminaire> lums;
  for (double x : {1.25, 3.75})
    for (double y : {1.0, 3.0}) lums.push_back(lambertian_at({x, y, 2.7}, 1000.0));
  const Scene s = scene_of(box_room(5, 4, 2.8, 0.2, 0.5, 0.7), lums);
  const auto grids = box_face_grids(5, 4, 2.8, 0.25);
  IndirectOptions fine;
  fine.quality = Quality::reference;
  fine.patch_size_m = 0.15;
  fine.max_patches_per_room = kMaxPatchesPerRoom;
  const IndirectResult ref = compute_indirect(s, grids, fine);
  // The promise's measure (report/diff.h): the difference in E = E_direct + E_indirect relative
  // to the point's E, but no less than 1 % of its face's largest E. The point sources' direct
  // light is exact (far_field_illuminance).
  std::vector<std::vector<double>> E(grids.size());
  std::vector<double> floor_lx(grids.size(), 0.0);
  for (size_t k = 0; k < grids.size(); ++k)
    for (size_t i = 0; i < grids[k].points.size(); ++i) {
      double e = ref.E_indirect_per_surface[k][i];
      for (const auto& lum : s.luminaires)
        e += far_field_illuminance(lum, grids[k].points[i], grids[k].normals[i]);
      E[k].push_back(e);
      floor_lx[k] = std::max(floor_lx[k], 0.01 * e);
    }
  const auto worst = [&](const IndirectResult& r) {
    double w = 0.0;
    for (size_t k = 0; k < grids.size(); ++k)
      for (size_t i = 0; i < grids[k].points.size(); ++i)
        w = std::max(w,
                     std::abs(r.E_indirect_per_surface[k][i] - ref.E_indirect_per_surface[k][i]) /
                         std::max(E[k][i], floor_lx[k]));
    return w;
  };
  IndirectOptions standard;
  const IndirectResult with_cells = compute_indirect(s, grids, standard);
  standard.refine_near_patches = false;
  const IndirectResult without = compute_indirect(s, grids, standard);
  std::printf(
      "[ corner cells ] largest difference to a 0.15 m mesh: %.2f %% with cells (%zu "
      "patches refined), %.2f %% without\n",
      100 * worst(with_cells), with_cells.refined_patches, 100 * worst(without));
  EXPECT_GT(with_cells.refined_patches, 0u);
  EXPECT_LT(worst(with_cells), 0.025);
  EXPECT_GT(worst(without), 0.05);  // the test sees the effect it guards
}

// The plan's estimate gathers its meshes at the probe points only and relies on the values there
// being the whole grid's, to the bit (indirect.h, gather_indirect): a point's cells are those of
// the patches it comes close to itself. Checked on every face of a box (points at corners and
// edges, where cells are made) and a workplane, against the whole grids gathered together.
TEST(Gather, ASubsetOfPointsGetsTheWholeGridsValuesToTheBit) {
  std::vector<Luminaire> lums;
  for (double x : {1.25, 3.75})
    for (double y : {1.0, 3.0}) lums.push_back(lambertian_at({x, y, 2.7}, 1000.0));
  const Scene s = scene_of(box_room(5, 4, 2.8, 0.2, 0.5, 0.7), lums);
  auto grids = box_face_grids(5, 4, 2.8, 0.25);
  grids.push_back(geometry::make_plane_grid("workplane", {0.5, 0.5, 0.75}, {1, 0, 0}, {0, 1, 0},
                                            4.0, 3.0, 0.25));
  const auto solution = solve_indirect(s, IndirectOptions{});
  const IndirectResult whole = gather_indirect(*solution, s, grids);
  ASSERT_GT(whole.refined_patches, 0u);  // cells are made, so the property is tested
  // Every 7th point of each grid, so the subset's neighbours are not gathered with it.
  std::vector<SurfaceGrid> subsets;
  std::vector<std::vector<size_t>> picked(grids.size());
  for (size_t k = 0; k < grids.size(); ++k) {
    SurfaceGrid g;
    g.name = grids[k].name;
    g.kind = SurfaceGrid::Kind::points;
    for (size_t i = 3; i < grids[k].points.size(); i += 7) {
      picked[k].push_back(i);
      g.points.push_back(grids[k].points[i]);
      g.normals.push_back(grids[k].normals[i]);
    }
    g.nu = static_cast<int>(g.points.size());
    g.nv = 1;
    subsets.push_back(g);
  }
  const IndirectResult part = gather_indirect(*solution, s, subsets);
  EXPECT_LT(part.refined_patches, whole.refined_patches);  // fewer cells made for fewer points
  for (size_t k = 0; k < grids.size(); ++k)
    for (size_t j = 0; j < picked[k].size(); ++j)
      EXPECT_EQ(part.E_indirect_per_surface[k][j], whole.E_indirect_per_surface[k][picked[k][j]])
          << grids[k].name << " point " << picked[k][j];
  // compute_indirect is the solve and the gather in one.
  EXPECT_EQ(compute_indirect(s, grids, IndirectOptions{}).E_indirect_per_surface,
            whole.E_indirect_per_surface);
}

// Cells only redistribute a patch's flux: their exitances average to the patch's (subcells.h).
TEST(Subcells, CellsKeepEachPatchsFlux) {
  const Scene s = scene_of(box_room(3, 2, 2.5, 0.3, 0.6, 0.8), {});
  const PatchMesh mesh = build_patch_mesh(s, 0.5);
  std::vector<char> refine(mesh.patches.size(), 1);
  const CellMesh cells = cell_mesh(mesh, refine);
  ASSERT_EQ(cells.mesh.patches.size(), mesh.patches.size() * kSubcellsPerSide * kSubcellsPerSide);
  std::vector<double> exitant(mesh.patches.size()), incident(cells.patch.size()),
      indirect(cells.patch.size());
  for (size_t i = 0; i < exitant.size(); ++i) exitant[i] = 100.0 + 10.0 * std::sin(double(i));
  for (size_t c = 0; c < incident.size(); ++c) {
    incident[c] = 0.5 + 0.3 * std::cos(0.7 * double(c));   // lm on a cell
    indirect[c] = 40.0 + 5.0 * std::sin(1.3 * double(c));  // lx
  }
  const SubcellExitance sub = cell_exitance(mesh, cells, exitant, incident, indirect);
  ASSERT_EQ(sub.refined_patches, mesh.patches.size());
  for (size_t i = 0; i < mesh.patches.size(); ++i) {
    const Patch& p = mesh.patches[i];
    double flux = 0.0, area = 0.0;
    for (int q = 0; q < kSubcellsPerSide * kSubcellsPerSide; ++q) {
      const size_t c = static_cast<size_t>(sub.first[i]) + q;
      flux += sub.exitance_lm_m2[c] * cells.mesh.patches[c].area_m2;
      area += cells.mesh.patches[c].area_m2;
      EXPECT_EQ(cells.patch[c], i);
    }
    EXPECT_NEAR(area, p.area_m2, 1e-12 * p.area_m2);
    EXPECT_NEAR(flux, exitant[i], 1e-12 * exitant[i]) << "patch " << i;
  }
}

// The far part of the cells' light is gathered once per distinct corner (subcells.h): the patches
// of one face share their corners, faces meeting at an edge do not, and the corners' bilinear
// weights give every cell centre the value of a light that changes linearly over the face.
TEST(Subcells, FarCornersAreSharedOnAFaceAndInterpolateLinearLight) {
  const Scene s = scene_of(box_room(3, 2, 2.5, 0.3, 0.6, 0.8), {});
  const PatchMesh mesh = build_patch_mesh(s, 0.5);
  const CellMesh cells = cell_mesh(mesh, std::vector<char>(mesh.patches.size(), 1));
  const FarCorners far = far_corners(mesh, cells);
  ASSERT_EQ(far.of_patch.size(), mesh.patches.size());
  // Brute force: the distinct (position, normal) pairs among all patches' polygon corners.
  std::vector<std::pair<Vec3, Vec3>> distinct;
  for (const Patch& p : mesh.patches)
    for (const Vec3& x : p.polygon) {
      bool seen = false;
      for (const auto& [y, n] : distinct)
        seen = seen || (glm::length(x - y) < 1e-9 && glm::length(p.normal - n) < 1e-9);
      if (!seen) distinct.emplace_back(x, p.normal);
    }
  EXPECT_EQ(far.corners.size(), distinct.size());
  // The floor alone: a lattice of nx x ny patches has (nx + 1) (ny + 1) corners.
  size_t floor_patches = 0;
  std::vector<size_t> floor_corners;
  for (size_t k = 0; k < mesh.patches.size(); ++k) {
    if (mesh.patches[k].face != FaceKind::floor) continue;
    ++floor_patches;
    for (size_t c : far.of_patch[k]) floor_corners.push_back(c);
  }
  std::sort(floor_corners.begin(), floor_corners.end());
  floor_corners.erase(std::unique(floor_corners.begin(), floor_corners.end()), floor_corners.end());
  ASSERT_EQ(floor_patches, 24u);  // 3 x 2 m at 0.5 m
  EXPECT_EQ(floor_corners.size(), 7u * 5u);
  // Each patch's corners are its polygon's, in order, and face its way.
  for (size_t k = 0; k < mesh.patches.size(); ++k)
    for (int c = 0; c < 4; ++c) {
      const FarCorners::Corner& corner = far.corners[far.of_patch[k][c]];
      EXPECT_LT(glm::length(corner.x - mesh.patches[k].polygon[c]), 1e-6) << k << " " << c;
      EXPECT_EQ(corner.normal, mesh.patches[k].normal);
      EXPECT_EQ(corner.room, mesh.patches[k].room);
    }
  // A light linear in position, taken at the corners, is the cells' centres' own light.
  const auto light = [](const Vec3& x) { return 40.0 + 3.0 * x.x - 2.0 * x.y + 5.0 * x.z; };
  for (size_t k = 0; k < mesh.patches.size(); ++k)
    for (int a = 0; a < kSubcellsPerSide; ++a)
      for (int b = 0; b < kSubcellsPerSide; ++b) {
        double lx = 0.0, weights = 0.0;
        for (int c = 0; c < 4; ++c) {
          lx += far_corner_weight(a, b, c) * light(far.corners[far.of_patch[k][c]].x);
          weights += far_corner_weight(a, b, c);
        }
        const Patch& cell =
            cells.mesh.patches[k * kSubcellsPerSide * kSubcellsPerSide + a * kSubcellsPerSide + b];
        EXPECT_NEAR(weights, 1.0, 1e-15);
        EXPECT_NEAR(lx, light(cell.centroid), 1e-12) << "patch " << k << " cell " << a << b;
      }
}

// ---------------------------------------------------------------------------------------------
// The plan decision.

TEST(Decision, SkipsWhenNotNeeded) {
  Scene s = scene_of(box_room(4, 4, 3, 0, 0, 0), {isotropic_at({2, 2, 2}, 10000.0)});
  s.surfaces = {geometry::make_plane_grid("floor", {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 4, 4, 0.5)};
  EXPECT_FALSE(decide_indirect(s).run);
  EXPECT_EQ(decide_indirect(s).reason, IndirectReason::no_reflectance);
  s.rooms[0].reflectance = {0.2, 0.5, 0.7};
  EXPECT_TRUE(decide_indirect(s).run);
  s.settings.indirect = IndirectMode::off;
  EXPECT_FALSE(decide_indirect(s).run);
  EXPECT_EQ(decide_indirect(s).reason, IndirectReason::off_in_settings);
  // Auto: a nearly black room, estimate far below 1 % of the direct light.
  s.settings.indirect = IndirectMode::automatic;
  s.rooms[0].reflectance = {0.001, 0.001, 0.001};
  const IndirectDecision d = decide_indirect(s);
  EXPECT_FALSE(d.run);
  EXPECT_EQ(d.reason, IndirectReason::below_threshold);
  EXPECT_NEAR(d.estimate_lx, 0.001 * 10000 / (80 * 0.999), 1e-9);
  s.settings.indirect = IndirectMode::on;
  EXPECT_TRUE(decide_indirect(s).run);
}

// A cabinet: light is blocked inside the room, which takes the clustered transfer with visibility
// per link above 1 100 patches (kClusteredVisibleAbovePatches) and its budget.
geometry::Obstacle cabinet() {
  geometry::Obstacle o;
  o.name = "cabinet";
  o.footprint = {{1, 1}, {2, 1}, {2, 1.5}, {1, 1.5}};
  o.z0 = 0.0, o.z1 = 1.8;
  o.reflectance = 0.5;
  return o;
}

// The dense budget: a convex room without obstacles of 4 000 to 10 000 patches keeps the dense
// path (30 x 20 x 3 m: 1 500 m^2 of faces, 6 000 patches at standard's 0.5 m, 9 375 at 0.4 m).
TEST(Decision, PatchBudgetIsEnforced) {
  Scene s = scene_of(box_room(30, 20, 3, 0.2, 0.5, 0.7), {isotropic_at({15, 10, 2}, 1e5)});
  IndirectOptions o;
  o.patch_size_m = 0.4;
  try {
    compute_indirect(s, {}, o);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("room 'box': "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("exceed the budget of 4000 patches"), std::string::npos);
  }
  o.patch_size_m = 0.0;  // automatic: coarsened to fit
  const IndirectResult r = compute_indirect(s, {}, o);
  EXPECT_LE(r.patches, 4000u);
  EXPECT_GT(r.patch_size_m, 0.5);
  EXPECT_EQ(r.clustered_rooms, 0u);
  EXPECT_FALSE(r.notes.empty());
  std::printf("[ budget ] 30 x 20 x 3 m: %zu patches of %.3g m (%.2f s)\n", r.patches,
              r.patch_size_m, r.seconds);
}

// ---------------------------------------------------------------------------------------------
// Obstacles: they reflect light and cast shadows, in the first bounce and between patches.

// 4 x 4 x 3 m box of uniform rho with a cabinet standing on the floor and a table top floating
// at 0.70-0.75 m, both of reflectance rho.
Scene box_with_obstacles(double rho, const Vec3& lum, bool with_obstacles = true) {
  Scene s = scene_of(box_room(4, 4, 3, rho, rho, rho), {isotropic_at(lum, 10000.0)});
  if (with_obstacles) {
    s.rooms[0].obstacles.push_back(
        geometry::make_box("cabinet", {0.3, 0.3, 0.0}, {1.1, 0.9, 1.2}, 0.3, rho));
    s.rooms[0].obstacles.push_back(
        geometry::make_box("table", {1.5, 1.5, 0.70}, {2.5, 2.5, 0.75}, 0.0, rho));
  }
  return s;
}

TEST(Obstacles, PatchesTileRoomAndObstacleSurfaces) {
  const Scene s = box_with_obstacles(0.5, {2, 2, 2.5});
  const PatchMesh m = build_patch_mesh(s, 0.25);
  double floor = 0.0, obstacle = 0.0, total = 0.0;
  for (const auto& p : m.patches) {
    total += p.area_m2;
    if (p.face == FaceKind::floor) floor += p.area_m2;
    if (p.face == FaceKind::obstacle) obstacle += p.area_m2;
  }
  // The cabinet's 0.8 x 0.6 footprint is cut out of the floor; it has sides and a top (no
  // bottom); the table has a top, a bottom and sides.
  const double cabinet = 0.8 * 0.6 + 2 * (0.8 + 0.6) * 1.2;
  const double table = 2 * 1.0 + 4 * 1.0 * 0.05;
  EXPECT_NEAR(floor, 16.0 - 0.48, 1e-9);
  EXPECT_NEAR(obstacle, cabinet + table, 1e-9);
  EXPECT_NEAR(total, room_surface_area(s.rooms[0]) - 0.48 + cabinet + table, 1e-9);
}

TEST(Obstacles, EnergyBalanceInClosedBoxWithObstacles) {
  // Direct lumens on room + obstacle faces = emitted flux (the faces close around the luminaire;
  // the shadow edges are resolved to the first bounce's pieces), VPL flux = sum rho x received,
  // and after N bounces the total exitant flux is rho R (1 - rho^N) / (1 - rho) (rows of a closed
  // room sum to 1).
  // The geometry (mesh, direct flux, form factors) does not depend on rho: built once.
  Scene s = box_with_obstacles(0.5, {2.3, 1.8, 2.5});
  PatchMesh mesh = build_patch_mesh(s, 0.3);
  const auto tree = tree_of(s);
  const std::vector<const geometry::Visibility*> occ = {tree.get()};
  FirstBounce fb = first_bounce(s, mesh, occ);
  const FormFactorMatrix F = form_factors(mesh, 0, occ[0], 5.0);
  double vpl = 0.0, rho_received = 0.0;
  for (size_t i = 0; i < mesh.patches.size(); ++i) {
    vpl += fb.vpl_flux_lm[i];
    rho_received += mesh.patches[i].reflectance * fb.incident_flux_lm[i];
  }
  EXPECT_NEAR(vpl / rho_received, 1.0, 1e-12);
  EXPECT_NEAR(vpl / fb.received_flux_lm, 0.5, 1e-12);
  const double direct_err = fb.received_flux_lm / fb.emitted_flux_lm - 1.0;
  EXPECT_NEAR(direct_err, 0.0, 5e-3);  // docs/indirect.md: within 0.5 %
  for (double rho : {0.2, 0.5, 0.8}) {
    for (auto& p : mesh.patches) p.reflectance = rho;
    std::vector<double> rhos;
    for (const auto& p : mesh.patches) rhos.push_back(p.reflectance);
    for (int bounces : {1, 2, 3, 5, 10, 0}) {
      const RadiosityResult sol = solve_radiosity(F, rhos, fb.incident_flux_lm, bounces, 1e-6);
      double total = 0.0;
      for (double x : sol.exitant_flux_lm) total += x;
      const double R = fb.received_flux_lm;
      const double expect =
          bounces == 0 ? rho * R / (1 - rho) : rho * R * (1 - std::pow(rho, bounces)) / (1 - rho);
      const double expect_emitted = expect * fb.emitted_flux_lm / R;
      std::printf(
          "[ energy obstacles rho %.1f bounces %-4s ] direct %+.2e  exitant %.2f lm, vs "
          "received %+.2e, vs emitted %+.2e  (%zu patches, max row corr %.1e)\n",
          rho, bounces ? std::to_string(bounces).c_str() : "auto", direct_err, total,
          total / expect - 1.0, total / expect_emitted - 1.0, mesh.patches.size(),
          F.max_row_correction);
      EXPECT_NEAR(total / expect, 1.0, bounces == 0 ? 1e-5 : 1e-9);
      EXPECT_NEAR(total / expect_emitted, 1.0, 5e-3);
    }
  }
}

TEST(Obstacles, TableShadowsTheFloorInTheFirstBounce) {
  // Luminaire straight above a 1 x 1 m table top at 0.75 m: the floor under it gets no direct
  // light (shadow 1.43 m wide), and, in the one-bounce solution, less reflected light than the
  // same point without the table (the table hides most of the lit ceiling and walls).
  const Vec3 lum(2, 2, 2.5);
  const Scene with = box_with_obstacles(0.5, lum), without = box_with_obstacles(0.5, lum, false);
  const PatchMesh mw = build_patch_mesh(with, 0.25), mo = build_patch_mesh(without, 0.25);
  const FirstBounce fw = first_bounce(with, mw, {tree_of(with).get()});
  const FirstBounce fo = first_bounce(without, mo, {nullptr});
  auto under_table = [](const PatchMesh& m, const FirstBounce& fb) {
    double flux = 0.0;
    for (size_t i = 0; i < m.patches.size(); ++i) {
      const auto& p = m.patches[i];
      if (p.face == FaceKind::floor && std::abs(p.centroid.x - 2) < 0.5 &&
          std::abs(p.centroid.y - 2) < 0.5)
        flux += fb.incident_flux_lm[i];
    }
    return flux;
  };
  EXPECT_GT(under_table(mo, fo), 100.0);
  EXPECT_LT(under_table(mw, fw), 1e-9);

  SurfaceGrid g;
  g.name = "under the table";
  g.kind = SurfaceGrid::Kind::points;
  g.points = {{2.0, 2.0, 0.0}, {2.3, 1.8, 0.0}, {3.7, 3.7, 0.0}};
  g.normals.assign(3, Vec3(0, 0, 1));
  g.active.assign(3, true);
  g.nu = 3;
  g.nv = 1;
  IndirectOptions one;
  one.bounces = 1;
  IndirectOptions one_shaded = one;
  one_shaded.visibility = tree_of(with);
  const auto Ew = compute_indirect(with, {g}, one_shaded).E_indirect_per_surface[0];
  const auto Eo = compute_indirect(without, {g}, one).E_indirect_per_surface[0];
  std::printf(
      "[ obstacle shadow ] first-bounce E_indirect with / without the table: centre %.2f / "
      "%.2f lx, (2.3, 1.8) %.2f / %.2f lx, corner (3.7, 3.7) %.2f / %.2f lx\n",
      Ew[0], Eo[0], Ew[1], Eo[1], Ew[2], Eo[2]);
  EXPECT_LT(Ew[0], 0.5 * Eo[0]);
  EXPECT_LT(Ew[1], 0.7 * Eo[1]);
  EXPECT_GT(Ew[2], 0.0);
}

// ---------------------------------------------------------------------------------------------
// A sphere-like room: in a sphere the form factor from any surface element to dA' is
// dA' / (4 pi R^2) whatever the element (cos = d / 2R at both ends), so the first reflection of
// ANY light is uniform, rho R_flux / A, however the direct light falls. A 24-gon prism as high as
// it is wide is the nearest room luxgrid can describe; it is not exact because its faces are flat
// (a face does not see itself: the floor gets nothing from the floor's light, a sphere's cap
// would) and its corners are not on one sphere (floor and ceiling centres are R from the middle,
// their rims R sqrt 2).

TEST(SphereLikeRoom, FirstBounceIsNearlyUniform) {
  Room r;
  r.name = "24-gon";
  const double R = 2.0;
  for (int k = 0; k < 24; ++k)
    r.outline.emplace_back(R * std::cos(2 * kPi * k / 24), R * std::sin(2 * kPi * k / 24));
  r.height = 2 * R;
  r.reflectance = {0.5, 0.5, 0.5};
  // Off-centre, so that the direct light is far from uniform.
  const Scene s = scene_of(r, {isotropic_at({0.9, 0.4, 3.0}, 10000.0)});
  const PatchMesh mesh = build_patch_mesh(s, 0.25);
  const FirstBounce fb = first_bounce(s, mesh, {nullptr});
  const FormFactorMatrix F = form_factors(mesh, 0, {}, 5.0);
  // Per face: direct and first-bounce indirect irradiance (flux received / area).
  std::map<std::pair<int, int>, std::array<double, 3>> faces;  // direct lm, indirect lm, area
  double area = 0.0;
  for (size_t i = 0; i < F.n; ++i) {
    double e1 = 0.0;
    for (size_t j = 0; j < F.n; ++j) e1 += F.at(i, j) * fb.vpl_flux_lm[j];
    const auto& p = mesh.patches[i];
    auto& f = faces[{static_cast<int>(p.face), p.face_index}];
    f[0] += fb.incident_flux_lm[i];
    f[1] += e1;
    f[2] += p.area_m2;
    area += p.area_m2;
  }
  const double uniform = 0.5 * fb.received_flux_lm / area;  // rho Phi / A
  double dmin = 1e300, dmax = 0, imin = 1e300, imax = 0;
  for (const auto& [key, f] : faces) {
    dmin = std::min(dmin, f[0] / f[2]), dmax = std::max(dmax, f[0] / f[2]);
    imin = std::min(imin, f[1] / f[2]), imax = std::max(imax, f[1] / f[2]);
  }
  std::printf(
      "[ sphere-like 24-gon ] direct per face %.1f .. %.1f lx (max/min %.2f); first bounce "
      "per face %.2f .. %.2f lx, rho Phi / A = %.2f lx (%+.1f %% .. %+.1f %%)\n",
      dmin, dmax, dmax / dmin, imin, imax, uniform, 100 * (imin / uniform - 1),
      100 * (imax / uniform - 1));
  EXPECT_GT(dmax / dmin, 3.0);   // the direct light is far from uniform...
  EXPECT_LT(imax / imin, 1.35);  // ...its first reflection nearly uniform
  EXPECT_NEAR(imin / uniform, 1.0, 0.25);
  EXPECT_NEAR(imax / uniform, 1.0, 0.25);
}

// ---------------------------------------------------------------------------------------------
// Bad input: exact messages.

TEST(BadInput, LeakingRoomAndBadObstacleAndBudgetNameTheObject) {
  auto message = [](const Scene& s, const IndirectOptions& o) -> std::string {
    try {
      compute_indirect(s, {}, o);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  Scene s = scene_of(box_room(4, 4, 3, 0.2, 0.5, 0.7), {isotropic_at({2, 2, 2}, 1e4)});
  s.rooms[0].outline = {{0, 0}, {4, 0}, {0, 4}, {4, 4}};  // a bow tie: edges 0 and 2 cross
  EXPECT_EQ(message(s, {}),
            "room 'box': outline edges 1 and 3 cross, so the room is not closed (it leaks); "
            "indirect light needs a simple outline");
  s = box_with_obstacles(0.5, {2, 2, 2.5});
  s.rooms[0].obstacles[1].reflectance = 1.2;
  EXPECT_EQ(message(s, {}),
            "room 'box', obstacle 'table': reflectance is 1.200000, expected a number in [0, 1]");
  s = scene_of(box_room(40, 20, 3, 0.2, 0.5, 0.7), {isotropic_at({20, 10, 2}, 1e5)});
  IndirectOptions o;
  o.patch_size_m = 0.05;  // convex, no obstacles: the clustered transfer's budget
  EXPECT_EQ(message(s, o),
            "room 'box': 784000 patches at a patch size of 0.05 m exceed the budget of 250000 "
            "patches per room");
  s.rooms[0].obstacles = {cabinet()};  // light blocked: the clustered budget all the same
  EXPECT_EQ(message(s, o),
            "room 'box': 784000 patches at a patch size of 0.05 m exceed the budget of 250000 "
            "patches per room");
  s = scene_of(box_room(30, 20, 3, 0.2, 0.5, 0.7), {isotropic_at({15, 10, 2}, 1e5)});
  o.patch_size_m = 0.4;  // convex, no obstacles, 4 000 to 10 000 patches: the dense budget
  EXPECT_EQ(message(s, o),
            "room 'box': 9375 patches at a patch size of 0.4 m exceed the budget of 4000 "
            "patches per room");
}

}  // namespace
}  // namespace luxgrid::calc::indirect
