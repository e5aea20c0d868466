// Patches cut into quarters where the light jumps (calc/indirect/split_mask.h,
// PatchMesh split_patches): the quarters tile what they replace, the cut follows the jump, and in
// an L-shaped room with an obstacle the cut solve is closer to a fine solve than the uncut one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "calc/indirect/indirect.h"
#include "calc/indirect/patches.h"
#include "calc/indirect/split_mask.h"
#include "calc/scene_visibility.h"
#include "geometry/surface_grid.h"
#include "tests/indirect/l_room.h"

namespace luxgrid::calc::indirect {
namespace {

TEST(Split, QuartersTileWhatTheyReplace) {
  const Scene s = l_scene("split");
  const PatchMesh mesh = build_patch_mesh(s, 0.5);
  std::vector<char> all(mesh.patches.size(), 1);
  const PatchMesh cut = split_patches(s, mesh, all);
  size_t parallelograms = 0;
  double area = 0.0, cut_area = 0.0;
  for (const Patch& p : mesh.patches) parallelograms += p.has_quarters ? 1 : 0, area += p.area_m2;
  for (const Patch& p : cut.patches) cut_area += p.area_m2;
  ASSERT_GT(parallelograms, 0u);
  ASSERT_LT(parallelograms, mesh.patches.size());  // the cabinet's footprint clips floor pieces
  EXPECT_EQ(cut.patches.size(), mesh.patches.size() + 3 * parallelograms);
  EXPECT_NEAR(cut_area, area, 1e-12 * area);
  ASSERT_EQ(cut.room_begin.size(), 2u);
  EXPECT_EQ(cut.room_begin[1], cut.patches.size());
  // Each quarter: a parallelogram of a quarter of its parent's area, on the parent's face, its
  // centroid one of the parent's quarter centroids.
  size_t k = 0;
  for (const Patch& p : mesh.patches) {
    if (!p.has_quarters) {
      EXPECT_EQ(cut.patches[k].centroid, p.centroid);
      ++k;
      continue;
    }
    for (int q = 0; q < 4; ++q, ++k) {
      const Patch& c = cut.patches[k];
      EXPECT_TRUE(c.has_quarters);
      EXPECT_NEAR(c.area_m2, 0.25 * p.area_m2, 1e-12);
      EXPECT_EQ(c.face, p.face);
      EXPECT_EQ(c.face_index, p.face_index);
      EXPECT_NEAR(glm::length(c.centroid - p.quarter_centroid[q]), 0.0, 1e-12);
      EXPECT_NEAR(glm::dot(c.normal, p.normal), 1.0, 1e-15);
    }
  }
}

TEST(Split, CutsBothSidesOfAJumpAndTheLargestFirst) {
  // One wall of a box room: its patches in a row along the wall, exitance uniform but for a step.
  Room r;
  r.name = "box";
  r.outline = {{0, 0}, {4, 0}, {4, 3}, {0, 3}};
  r.height = 0.5;
  r.reflectance = {0.5, 0.5, 0.5};
  Scene s;
  s.rooms = {r};
  const PatchMesh mesh = build_patch_mesh(s, 0.5);
  std::vector<size_t> wall0;  // the wall along y = 0, by x
  for (size_t i = 0; i < mesh.patches.size(); ++i)
    if (mesh.patches[i].face == FaceKind::wall && mesh.patches[i].face_index == 0)
      wall0.push_back(i);
  ASSERT_EQ(wall0.size(), 8u);
  std::sort(wall0.begin(), wall0.end(), [&](size_t a, size_t b) {
    return mesh.patches[a].centroid.x < mesh.patches[b].centroid.x;
  });
  std::vector<double> flux(mesh.patches.size());
  for (size_t i = 0; i < flux.size(); ++i) flux[i] = 10.0 * mesh.patches[i].area_m2;
  const size_t n = mesh.patches.size();
  EXPECT_EQ(std::count(flux.begin(), flux.end(), 0.0), 0);
  const auto uniform = patches_to_split(mesh, 0, n, flux, kSplitJump, n);
  EXPECT_EQ(std::count(uniform.begin(), uniform.end(), 1), 0);
  // A step of 50 % between the 4th and 5th patch, and one of 35 % between the 7th and 8th.
  for (size_t k = 4; k < 8; ++k) flux[wall0[k]] *= 0.5;
  flux[wall0[7]] *= 0.65;
  const auto cut = patches_to_split(mesh, 0, n, flux, kSplitJump, n);
  for (size_t k = 0; k < 8; ++k)
    EXPECT_EQ(cut[wall0[k]], k == 3 || k == 4 || k == 6 || k == 7 ? 1 : 0) << k;
  EXPECT_EQ(std::count(cut.begin(), cut.end(), 1), 4);
  // Room for two cuts (6 added patches): the 50 % step's two patches.
  const auto two = patches_to_split(mesh, 0, n, flux, kSplitJump, 6);
  EXPECT_EQ(std::count(two.begin(), two.end(), 1), 2);
  EXPECT_EQ(two[wall0[3]], 1);
  EXPECT_EQ(two[wall0[4]], 1);
}

// The largest |a - b| / b over the points where b exceeds 1 % of its largest value.
double worst_relative(const std::vector<double>& a, const std::vector<double>& b) {
  const double top = *std::max_element(b.begin(), b.end());
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
    if (b[i] > 0.01 * top) worst = std::max(worst, std::abs(a[i] - b[i]) / b[i]);
  return worst;
}

TEST(Split, AnLShapedRoomComesCloserToAFineSolve) {
  const Scene s = l_scene("split");
  VisibilityDecision decision;
  const std::shared_ptr<const geometry::Visibility> vis = make_visibility(s, decision);
  ASSERT_TRUE(vis);
  // The floor of the short leg and the wall at its end, lit round the corner.
  const std::vector<geometry::SurfaceGrid> grids = {
      geometry::make_plane_grid("short leg floor", {0, 2, 0}, {1, 0, 0}, {0, 1, 0}, 3, 2, 0.2),
      geometry::make_plane_grid("end wall", {0, 4, 0}, {1, 0, 0}, {0, 0, 1}, 3, 2.5, 0.25)};
  const auto run = [&](double size_m, bool split) {
    IndirectOptions o;
    o.quality = Quality::standard;
    o.patch_size_m = size_m;
    o.visibility = vis;
    o.split_patches = split;
    return compute_indirect(s, grids, o);
  };
  const IndirectResult fine = run(0.2, false);
  const IndirectResult uncut = run(0.8, false);
  const IndirectResult cut = run(0.8, true);
  EXPECT_EQ(uncut.split_patches, 0u);
  EXPECT_GT(cut.split_patches, 0u);
  EXPECT_LT(cut.patches, 4 * uncut.patches);
  for (size_t g = 0; g < grids.size(); ++g) {
    const double before =
        worst_relative(uncut.E_indirect_per_surface[g], fine.E_indirect_per_surface[g]);
    const double after =
        worst_relative(cut.E_indirect_per_surface[g], fine.E_indirect_per_surface[g]);
    std::printf("%s: uncut %.3f %%, cut %.3f %% from the 0.2 m solve\n", grids[g].name.c_str(),
                100 * before, 100 * after);
    // Measured: see the printed figures; the cut solve must be clearly closer, not merely equal.
    EXPECT_LT(after, 0.8 * before) << grids[g].name;
  }
}

// The local step's mesh (IndirectOptions::refine_near): every parallelogram with a corner inside
// a ball is cut into quarters, every one whose centroid is further than the ball's radius plus
// its diameter is not, the quarters tile what they replace, and the solve counts what it cut.
TEST(Split, RefineNearCutsThePatchesReachingIntoItsBalls) {
  const Scene s = l_scene("split");
  const PatchMesh whole = build_patch_mesh(s, 0.5);
  IndirectOptions o;
  o.quality = Quality::standard;
  o.patch_size_m = 0.5;
  o.split_patches = false;  // the light's own cut is Split's other tests'
  o.refine_near = {{{1.0, 3.0, 0.0}, 0.6}, {{6.0, 1.0, 1.5}, 0.3}};
  const std::unique_ptr<const IndirectSolution> solved = solve_indirect(s, o);
  const PatchMesh& mesh = solved->mesh;
  const auto kept = [&](const Patch& p) {
    return std::any_of(mesh.patches.begin(), mesh.patches.end(), [&](const Patch& q) {
      return glm::length(q.centroid - p.centroid) < 1e-12 && q.area_m2 == p.area_m2;
    });
  };
  size_t cut = 0, inside = 0, outside = 0;
  double area = 0.0, cut_area = 0.0;
  for (const Patch& p : whole.patches) {
    area += p.area_m2;
    if (!p.has_quarters) continue;
    const bool reaches = std::any_of(p.polygon.begin(), p.polygon.end(), [&](const Vec3& v) {
      return std::any_of(o.refine_near.begin(), o.refine_near.end(), [&](const Neighbourhood& n) {
        return glm::length(v - n.point) < n.radius_m;
      });
    });
    const bool far = std::all_of(o.refine_near.begin(), o.refine_near.end(), [&](const auto& n) {
      return glm::length(p.centroid - n.point) > n.radius_m + p.diameter_m;
    });
    if (reaches) {
      EXPECT_FALSE(kept(p)) << p.centroid.x << " " << p.centroid.y << " " << p.centroid.z;
    }
    if (far) {
      EXPECT_TRUE(kept(p)) << p.centroid.x << " " << p.centroid.y << " " << p.centroid.z;
    }
    inside += reaches ? 1 : 0;
    outside += far ? 1 : 0;
    cut += kept(p) ? 0 : 1;
  }
  for (const Patch& p : mesh.patches) cut_area += p.area_m2;
  EXPECT_GT(inside, 4u);    // the floor near (1, 3) and the wall at x = 6: several of each
  EXPECT_GT(outside, 50u);  // most of the room
  EXPECT_EQ(solved->result.locally_refined_patches, cut);
  EXPECT_EQ(mesh.patches.size(), whole.patches.size() + 3 * cut);
  EXPECT_NEAR(cut_area, area, 1e-12 * area);
}

}  // namespace
}  // namespace luxgrid::calc::indirect
