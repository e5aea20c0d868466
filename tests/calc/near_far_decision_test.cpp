// The near/far decision by an error bound (calc/nearfield/far_field_bound.h, docs/nearfield.md,
// "The near/far decision"): real luminaires tilted and aimed at a floor and a wall from 1 to 12 D;
// the hybrid of `standard` is within 1 % of `reference` at every point brighter than 1 % of its
// surface's maximum, and `high` within 0.3 % (the promises of docs/project-format.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "../nearfield/nearfield_test_support.h"
#include "calc/nearfield/far_field_bound.h"
#include "calc/nearfield/illuminance.h"
#include "calc/pipeline.h"
#include "calc/scene_far_field_bounds.h"
#include "photometry/photometry.h"
#include "project/project_file.h"

namespace luxgrid::calc {
namespace {

using nearfield::Emitter;
using nearfield::Model;
using nearfield::NearFieldSwitch;

// The reference's own tolerance here: 1e-5 relative, 300 times below the 0.3 % bar.
constexpr double kReferenceTol = 1e-5;
// Points below this fraction of the surface's maximum are not held to the promise
// (docs/accuracy.md).
constexpr double kBrightFraction = 0.01;
// Receivers per distance on each surface, spread around the emitter (12 distances x 10).
constexpr int kAzimuths = 10;

photometry::Photometry load(const std::string& rel) {
  return photometry::load_photometry_file(std::string(LUXGRID_SOURCE_DIR) +
                                          "/tests/data/photometry/" + rel);
}

struct Receiver {
  Vec3 p, n;
};

// A floor below and a wall beside the emitter, receivers 1 to 12 D from its centre.
std::vector<std::vector<Receiver>> floor_and_wall(const Emitter& e) {
  const double D = e.largest_dimension_m;
  std::vector<Receiver> floor, wall;
  const double h = 0.9 * D;  // floor and wall 0.9 D away, so the nearest receivers sit at ~1 D
  for (double r : {1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 12.0}) {
    const double in_plane = std::sqrt(std::max(0.0, r * r * D * D - h * h));
    for (int k = 0; k < kAzimuths; ++k) {
      const double a = 2.0 * kPi * k / kAzimuths;
      floor.push_back(
          {e.centroid + Vec3(in_plane * std::cos(a), in_plane * std::sin(a), -h), Vec3(0, 0, 1)});
      wall.push_back(
          {e.centroid + Vec3(h, in_plane * std::cos(a), in_plane * std::sin(a)), Vec3(-1, 0, 0)});
    }
  }
  return {floor, wall};
}

struct Worst {
  double standard = 0.0, high = 0.0, five_times = 0.0;
};

// Brute force: E = (1/A) integral of I(w) cos_r / d^2 dA (L = I / (A |cos_e|), Luksch et al. 2020
// Eq. 2), the centroid rule on each fan triangle cut into n x n similar triangles: an estimator
// that shares nothing with the reference's adaptive cubature.
double brute_force(const Emitter& e, const Vec3& x, const Vec3& n_x, int n) {
  double sum = 0.0;
  for (size_t k = 0; k < e.vertices.size(); ++k) {
    const Vec3 a = e.centroid, b = e.vertices[k], c = e.vertices[(k + 1) % e.vertices.size()];
    const Vec3 u = (b - a) / double(n), v = (c - a) / double(n);
    const double cell = 0.5 * glm::length(glm::cross(u, v));
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        const Vec3 corner = a + double(i) * u + double(j) * v;
        for (int up = 0; up < (i + j + 1 < n ? 2 : 1); ++up) {
          const Vec3 y = up == 0 ? corner + (u + v) / 3.0 : corner + 2.0 * (u + v) / 3.0;
          const Vec3 r = x - y;
          const double d = glm::length(r);
          const double cos_r = -glm::dot(n_x, r) / d;
          if (cos_r > 0.0) sum += e.intensity_towards(r / d) * cos_r / (d * d) * cell;
        }
      }
  }
  return sum / e.area_m2;
}

Worst check_scene(const std::string& what, Emitter e) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto standard_bound =
      nearfield::build_far_field_bound(e, Model::standard(), nearfield::kStandardPromise);
  const auto t1 = std::chrono::steady_clock::now();
  const auto high_bound =
      nearfield::build_far_field_bound(e, Model::high(), nearfield::kHighPromise);
  const auto t2 = std::chrono::steady_clock::now();
  // The maps a run builds: only what these receivers ask (nearfield::MapDemand).
  nearfield::MapDemand demand;
  for (const auto& surface : floor_and_wall(e))
    for (const auto& r : surface) {
      const Vec3 d = r.p - e.centroid;
      demand.add(e.world_to_local * glm::normalize(d), glm::length(d) / e.largest_dimension_m);
    }
  const auto standard_for_scene =
      nearfield::build_far_field_bound(e, Model::standard(), nearfield::kStandardPromise, &demand);
  const auto high_for_scene =
      nearfield::build_far_field_bound(e, Model::high(), nearfield::kHighPromise, &demand);
  std::printf("%s: map built in %.0f ms (standard), %.0f ms (high)\n", what.c_str(),
              1e3 * std::chrono::duration<double>(t1 - t0).count(),
              1e3 * std::chrono::duration<double>(t2 - t1).count());
  Worst worst;
  const char* names[] = {"floor", "wall"};
  int s = 0;
  for (const auto& surface : floor_and_wall(e)) {
    std::vector<double> ref;
    for (const auto& r : surface)
      ref.push_back(nearfield::illuminance(e, r.p, r.n, Model::reference(kReferenceTol)));
    const double max_ref = *std::max_element(ref.begin(), ref.end());
    EXPECT_GT(max_ref, 0.0) << what;
    for (size_t i = 0; i < surface.size(); ++i) {
      if (ref[i] < kBrightFraction * max_ref) continue;
      e.far_bound = standard_bound;
      const double es =
          nearfield::hybrid_illuminance(e, surface[i].p, surface[i].n, Model::standard());
      e.far_bound = high_bound;
      const double eh = nearfield::hybrid_illuminance(e, surface[i].p, surface[i].n, Model::high());
      const double err_s = std::abs(es - ref[i]) / ref[i], err_h = std::abs(eh - ref[i]) / ref[i];
      EXPECT_LE(err_s, nearfield::kStandardPromise) << what << " " << names[s] << " point " << i;
      EXPECT_LE(err_h, nearfield::kHighPromise) << what << " " << names[s] << " point " << i;
      worst.standard = std::max(worst.standard, err_s);
      worst.high = std::max(worst.high, err_h);
      e.far_bound = standard_for_scene;
      const double es_scene =
          nearfield::hybrid_illuminance(e, surface[i].p, surface[i].n, Model::standard());
      e.far_bound = high_for_scene;
      const double eh_scene =
          nearfield::hybrid_illuminance(e, surface[i].p, surface[i].n, Model::high());
      EXPECT_LE(std::abs(es_scene - ref[i]) / ref[i], nearfield::kStandardPromise)
          << what << " " << names[s] << " point " << i << " (map for the scene)";
      EXPECT_LE(std::abs(eh_scene - ref[i]) / ref[i], nearfield::kHighPromise)
          << what << " " << names[s] << " point " << i << " (map for the scene)";
      // What the five-times rule gave, printed to show the scene tests the decision.
      e.far_bound = nullptr;
      const double e5 =
          nearfield::hybrid_illuminance(e, surface[i].p, surface[i].n, Model::standard());
      worst.five_times = std::max(worst.five_times, std::abs(e5 - ref[i]) / ref[i]);
    }
    ++s;
  }
  std::printf(
      "near/far by error bound, %s: worst point standard %.3f %%, high %.3f %% (five-times rule: "
      "%.3f %%); "
      "standard: out to %.1f D, median %.1f D\n",
      what.c_str(), 100 * worst.standard, 100 * worst.high, 100 * worst.five_times,
      standard_bound->max_over_D, standard_bound->median_over_D);
  return worst;
}

Emitter tilted(const photometry::Photometry& ph, double rx_deg, double ry_deg, double rz_deg) {
  return nearfield::make_emitter(
      ph.opening, Vec3(0.0, 0.0, 3.0),
      rotation_xyz(rx_deg * kDegToRad, ry_deg * kDegToRad, rz_deg * kDegToRad), ph.distribution);
}

TEST(NearFarDecision, LedvanceFloodTilted) {
  // The flood: 8 C planes 45 degrees apart, 0.65 m opening, rotated [20, -35, 60].
  check_scene("ledvance_flmax_asym_isym0 [20,-35,60]",
              tilted(load("ldt/ledvance_flmax_asym_isym0.ldt"), 20, -35, 60));
}

TEST(NearFarDecision, ReferenceAgreesWithBruteForce) {
  // The scenes' truth is the reference; check it where the issue measured the flood (a floor
  // point 5 m away) and at two tilted receivers 3 and 8 D away. 400 x 400 cells per fan triangle:
  // the centroid rule's error is O(h^2), ~1e-5 here (halving n moved it by < 2e-5, measured).
  const Emitter e = tilted(load("ldt/ledvance_flmax_asym_isym0.ldt"), 20, -35, 60);
  const double D = e.largest_dimension_m;
  const Receiver probes[] = {
      {Vec3(5.0 * std::cos(0.3), 5.0 * std::sin(0.3), 0.0), Vec3(0, 0, 1)},
      {e.centroid + Vec3(0.5, -2.0, -2.0) * (3.0 * D / 3.0), glm::normalize(Vec3(0.2, 0.5, 1))},
      {e.centroid + Vec3(-4.0, 6.0, -3.0) * (8.0 * D / std::sqrt(61.0)), Vec3(0.6, -0.8, 0)}};
  for (const auto& r : probes) {
    const double ref = nearfield::illuminance(e, r.p, r.n, Model::reference(kReferenceTol));
    const double brute = brute_force(e, r.p, r.n, 400);
    ASSERT_GT(brute, 0.0);
    // 1e-4: ten times the brute force's own error, 30 times below the 0.3 % bar.
    EXPECT_NEAR(ref / brute, 1.0, 1e-4) << "at " << r.p.x << ", " << r.p.y << ", " << r.p.z;
    std::printf("reference %.6g lx, brute force %.6g lx (%.2e)\n", ref, brute, ref / brute - 1.0);
  }
}

TEST(NearFarDecision, MirelTilted) {
  // The office's Mirel (kink at gamma 35 on C45), tilted so the kink sweeps floor and wall.
  check_scene("zumtobel_mirel_isym4 [15,25,10]",
              tilted(load("ldt/zumtobel_mirel_isym4.ldt"), 15, 25, 10));
}

TEST(NearFarDecision, ErcoSpotTilted) {
  check_scene("erco_qrcbc35_lm86_spot [30,-20,0]",
              tilted(load("ies/erco_qrcbc35_lm86_spot.ies"), 30, -20, 0));
}

TEST(NearFarDecision, RoadLuminaireTilted) {
  check_scene("rab_roadway_bilateral_lm02 [10,15,40]",
              tilted(load("ies/rab_roadway_bilateral_lm02.ies"), 10, 15, 40));
}

TEST(NearFarDecision, BatwingPanelTilted) {
  photometry::Photometry ph;
  ph.distribution = nearfield::testing::batwing();
  ph.opening.shape = photometry::LuminousOpening::Shape::rectangle;
  ph.opening.length = 0.6;
  ph.opening.width = 0.6;
  check_scene("batwing 0.6 m square [25,-10,30]", tilted(ph, 25, -10, 30));
}

TEST(NearFarDecision, BundledOfficeThroughThePipeline) {
  // The office: desk probe (2, 2, 0.75) was 630.5 lx at standard and high against 618.6
  // at reference (+1.9 %), 8 of 240 workplane points > 1 % off. Direct light only.
  Scene scene =
      project::load_project(std::string(LUXGRID_SOURCE_DIR) + "/examples/office/project.json")
          .scene;
  scene.settings.indirect = IndirectMode::off;
  // Its observers surface needs reflected light (UGR); this test is about direct light only.
  std::erase_if(scene.surfaces,
                [](const auto& g) { return g.kind == geometry::SurfaceGrid::Kind::observers; });
  auto run = [&](Quality q) {
    scene.settings.quality = q;
    return run_scene(scene);
  };
  const Results ref = run(Quality::reference), standard = run(Quality::standard),
                high = run(Quality::high);
  // The office's panels have openings: the switch is by the error-bound map, one per distinct
  // emitter.
  EXPECT_EQ(standard.plan.near_switch, nearfield::NearFieldSwitch::automatic);
  EXPECT_FALSE(standard.plan.near_far.empty());
  for (size_t k = 0; k < ref.surfaces.size(); ++k) {
    const auto& r = ref.surfaces[k].E_direct;
    const double max_ref = *std::max_element(r.begin(), r.end());
    double worst_s = 0.0, worst_h = 0.0;
    for (size_t i = 0; i < r.size(); ++i) {
      if (r[i] < kBrightFraction * max_ref) continue;
      worst_s = std::max(worst_s, std::abs(standard.surfaces[k].E_direct[i] - r[i]) / r[i]);
      worst_h = std::max(worst_h, std::abs(high.surfaces[k].E_direct[i] - r[i]) / r[i]);
    }
    EXPECT_LE(worst_s, nearfield::kStandardPromise) << ref.surfaces[k].grid.name;
    EXPECT_LE(worst_h, nearfield::kHighPromise) << ref.surfaces[k].grid.name;
    std::printf("office %s: worst point standard %.3f %%, high %.3f %%\n",
                ref.surfaces[k].grid.name.c_str(), 100 * worst_s, 100 * worst_h);
  }
}

}  // namespace
}  // namespace luxgrid::calc
