// The plan's own error estimate (calc/plan_estimates.h, docs/accuracy.md "The plan's own
// estimate"): each approximation's estimate is checked against what it estimates.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "calc/indirect/clustered.h"
#include "calc/indirect/indirect.h"
#include "calc/nearfield/far_field_bound.h"
#include "calc/pipeline.h"
#include "calc/plan_estimates.h"
#include "project/project_file.h"

namespace luxgrid::calc {
namespace {

Scene office() {
  Scene scene =
      project::load_project(std::string(LUXGRID_SOURCE_DIR) + "/examples/office/project.json")
          .scene;
  // The glare surface is not what these tests look at.
  std::erase_if(scene.surfaces,
                [](const auto& g) { return g.kind == geometry::SurfaceGrid::Kind::observers; });
  return scene;
}

// The estimate from the probes' own values (what the plan computes without gathering every
// point) is patch_size_estimate's to the bit where no probe is darker than 1 % of the bound on
// the surface's largest E, or where no darker one can exceed the brighter ones' largest figure
// whatever the floor; where one could, the floor may decide it, and the probes give a bound.
TEST(PlanEstimates, PatchSizeEstimateAtTheProbesIsTheWholeGridsOrBoundsIt) {
  geometry::SurfaceGrid grid =
      geometry::make_plane_grid("g", {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 2.0, 2.0, 0.25);
  const size_t n = grid.points.size();
  std::vector<double> E_direct(n), E_ind(n), E(n);
  for (size_t i = 0; i < n; ++i) {
    E_direct[i] = 300.0 + 37.0 * std::sin(0.7 * static_cast<double>(i));
    E_ind[i] = 80.0 + 11.0 * std::cos(0.3 * static_cast<double>(i));
    E[i] = E_direct[i] + E_ind[i];
  }
  const std::vector<size_t> probes = probe_points(grid);
  std::vector<double> E_ind_probe, coarse;
  for (size_t k = 0; k < probes.size(); ++k) {
    E_ind_probe.push_back(E_ind[probes[k]]);
    coarse.push_back(E_ind[probes[k]] * (1.0 + 0.01 * std::sin(static_cast<double>(k))));
  }
  const double whole = patch_size_estimate(grid, E, E_ind, probes, coarse);
  ASSERT_GT(whole, 0.0);
  // A bound of the reflected light well above its largest value (91 lx): the floor is then at
  // most 1 % of 337 + 400 lx, below every probe's 300 lx and more.
  const ProbeFigure bright =
      patch_size_estimate_at_probes(grid, E_direct, probes, E_ind_probe, coarse, 400.0);
  EXPECT_TRUE(bright.exact);
  EXPECT_EQ(bright.figure, whole);
  // A dark probe (2 lx, below 1 % of the bound) with a large difference: the floor may decide
  // the figure, so the probes only bound it. The bound holds for any largest E from the known
  // 337 lx up: checked against the whole grid's figure with that point at 2 lx, whatever the
  // other points' reflected light (here the grid's own, and ten times it).
  std::vector<double> dark_direct = E_direct, dark_probe = E_ind_probe;
  dark_direct[probes[5]] = 1.0;
  dark_probe[5] = 1.0;
  const ProbeFigure dark =
      patch_size_estimate_at_probes(grid, dark_direct, probes, dark_probe, coarse, 400.0);
  EXPECT_FALSE(dark.exact);
  for (const double scale : {1.0, 10.0}) {
    std::vector<double> dark_E(n), dark_ind(n);
    for (size_t i = 0; i < n; ++i) {
      dark_ind[i] = scale * E_ind[i];
      dark_E[i] = E_direct[i] + dark_ind[i];
    }
    dark_E[probes[5]] = 2.0;
    dark_ind[probes[5]] = 1.0;
    std::vector<double> dark_E_probe;
    for (size_t k = 0; k < probes.size(); ++k) dark_E_probe.push_back(dark_ind[probes[k]]);
    // The probes' own values as the bound saw them (the scale changes them too).
    const ProbeFigure bound = patch_size_estimate_at_probes(grid, dark_direct, probes, dark_E_probe,
                                                            coarse, 400.0 * scale);
    EXPECT_GE(bound.figure, patch_size_estimate(grid, dark_E, dark_ind, probes, coarse))
        << "scale " << scale;
  }
  // The same dark probe with a small difference (0.001 lx: at most 0.001 / 3.4 over the least
  // floor, 1 % of the 337 lx known), below the bright probes' largest: the floor cannot decide
  // the figure, which is the whole grid's (with that point's E of 2 lx), to the bit.
  std::vector<double> dark_coarse = coarse;
  dark_coarse[5] = 1.001;
  std::vector<double> dark_E = E, dark_ind = E_ind;
  dark_E[probes[5]] = 2.0;
  dark_ind[probes[5]] = 1.0;
  const double dark_whole = patch_size_estimate(grid, dark_E, dark_ind, probes, dark_coarse);
  ASSERT_GT(dark_whole, 0.001 / 3.0);
  const ProbeFigure small =
      patch_size_estimate_at_probes(grid, dark_direct, probes, dark_probe, dark_coarse, 400.0);
  EXPECT_TRUE(small.exact);
  EXPECT_EQ(small.figure, dark_whole);
}

// The shadow probes are the active points with the weakest direct light that the evenly spread
// probes left out, each once: checked against sorting every point by E_direct.
TEST(PlanEstimates, ShadowProbesAreTheDarkestPointsNotYetPicked) {
  geometry::SurfaceGrid grid =
      geometry::make_plane_grid("g", {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 4.0, 4.0, 0.25);
  const size_t n = grid.points.size();
  grid.active.assign(n, true);
  grid.active[3] = false;  // the darkest point, inactive: not a probe
  std::vector<double> E_direct(n);
  for (size_t i = 0; i < n; ++i)
    E_direct[i] = 50.0 + 40.0 * std::sin(0.37 * static_cast<double>(i));
  E_direct[3] = -1.0;
  std::vector<size_t> picked = probe_points(grid);
  const size_t spread = picked.size();
  ASSERT_EQ(spread, kProbePointsPerSurface);
  add_shadow_probes(grid, E_direct, picked);
  ASSERT_EQ(picked.size(), spread + kShadowProbesPerSurface);
  std::vector<size_t> expected;
  for (size_t i = 0; i < n; ++i)
    if (grid.active[i] &&
        std::find(picked.begin(), picked.begin() + static_cast<std::ptrdiff_t>(spread), i) ==
            picked.begin() + static_cast<std::ptrdiff_t>(spread))
      expected.push_back(i);
  std::sort(expected.begin(), expected.end(),
            [&](size_t a, size_t b) { return E_direct[a] < E_direct[b]; });
  expected.resize(kShadowProbesPerSurface);
  EXPECT_EQ(std::vector<size_t>(picked.begin() + static_cast<std::ptrdiff_t>(spread), picked.end()),
            expected);
  // A surface with fewer points than probes: every active point once, nothing added.
  geometry::SurfaceGrid small =
      geometry::make_plane_grid("s", {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.0, 1.0, 0.25);
  std::vector<size_t> all = probe_points(small);
  add_shadow_probes(small, std::vector<double>(small.points.size(), 1.0), all);
  EXPECT_EQ(all.size(), small.points.size());
}

// Richardson's estimate with the order measured recovers E(h) - E(0) exactly on sequences
// E(h) = E0 + c h^p with p inside [kMinPatchOrder, kMaxPatchOrder] (to rounding: 1e-12
// relative); outside it the estimate is the range's end's, d1 / 3 or d1.
TEST(PlanEstimates, RichardsonRecoversTheErrorOfAKnownOrder) {
  const double E0 = 100.0, c = 3.0, h = 0.5;
  const auto E = [&](double size, double p) { return E0 + c * std::pow(size, p); };
  for (double p : {1.0, 1.3, 1.5, 2.0}) {
    const double d1 = std::abs(E(h, p) - E(2 * h, p)), d2 = std::abs(E(2 * h, p) - E(4 * h, p));
    const PatchErrorEstimate r = richardson_patch_error(d1, d2);
    EXPECT_NEAR(r.order, p, 1e-12) << p;
    EXPECT_NEAR(r.error, E(h, p) - E0, 1e-12 * E0) << p;
  }
  // Faster than second order: clamped to 2, the estimate d1 / 3 is above the true error.
  {
    const double p = 3.0;
    const double d1 = E(2 * h, p) - E(h, p), d2 = E(4 * h, p) - E(2 * h, p);
    const PatchErrorEstimate r = richardson_patch_error(d1, d2);
    EXPECT_EQ(r.order, kMaxPatchOrder);
    EXPECT_DOUBLE_EQ(r.error, d1 / 3.0);
    EXPECT_GT(r.error, E(h, p) - E0);
  }
  // Slower than first order, or no order measured (the coarse difference no larger than the
  // fine one): the first-order estimate, the fine difference itself.
  for (double d2 : {0.0, 0.5e-2, 1e-2, 1.5e-2}) {
    const PatchErrorEstimate r = richardson_patch_error(1e-2, d2);
    EXPECT_EQ(r.order, kMinPatchOrder);
    EXPECT_EQ(r.error, 1e-2);
  }
  // No 4h level: first order assumed, the estimate is the difference itself.
  EXPECT_EQ(richardson_patch_error(1e-2, -1.0).error, 1e-2);
  EXPECT_EQ(richardson_patch_error(1e-2, -1.0).order, 1.0);
  // The two finer meshes agree: nothing to extrapolate.
  EXPECT_EQ(richardson_patch_error(0.0, 1e-2).error, 0.0);
}

// On a surface: the probes' values at h, 2h and 4h follow E_k(h) = E0_k + c_k h^p with one p
// and a different c_k per probe; d1 and d2 are the largest differences relative to each point's
// E, so their ratio is 2^p wherever the largest of both is at the same probe (it is: each
// probe's d2 is 2^p times its d1), and the estimate is the largest relative error at h.
TEST(PlanEstimates, RichardsonOnASurfaceMeasuresTheOrderFromTheProbes) {
  geometry::SurfaceGrid grid =
      geometry::make_plane_grid("g", {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 2.0, 2.0, 0.25);
  const size_t n = grid.points.size();
  const double h = 0.5, p = 1.4;
  std::vector<double> E_direct(n), E0(n), c(n);
  for (size_t i = 0; i < n; ++i) {
    E_direct[i] = 300.0 + 37.0 * std::sin(0.7 * static_cast<double>(i));
    E0[i] = 80.0 + 11.0 * std::cos(0.3 * static_cast<double>(i));
    c[i] = 4.0 * std::sin(1.3 * static_cast<double>(i));  // either sign
  }
  const auto E_ind = [&](size_t i, double size) { return E0[i] + c[i] * std::pow(size, p); };
  std::vector<double> E(n), E_ind_h(n);
  for (size_t i = 0; i < n; ++i) E_ind_h[i] = E_ind(i, h), E[i] = E_direct[i] + E_ind_h[i];
  const std::vector<size_t> probes = probe_points(grid);
  std::vector<double> at_2h, at_4h;
  double truth = 0.0;  // the largest |E(h) - E(0)| / E over the probes
  for (size_t i : probes) {
    at_2h.push_back(E_ind(i, 2 * h));
    at_4h.push_back(E_ind(i, 4 * h));
    truth = std::max(truth, std::abs(E_ind_h[i] - E0[i]) / E[i]);
  }
  const double d1 = patch_size_estimate(grid, E, E_ind_h, probes, at_2h);
  const double d2 = coarse_level_difference(grid, E, probes, at_2h, at_4h);
  const PatchErrorEstimate r = richardson_patch_error(d1, d2);
  EXPECT_NEAR(r.order, p, 1e-9);
  EXPECT_NEAR(r.error, truth, 1e-9 * truth);
}

// After a local step: probes the mesh was cut around are estimated by their own last difference
// (first order); the others by their distance from E_ind(0) extrapolated from h and 2h with the
// order measured over them alone, so a move towards that value lowers their figure and one away
// raises it. Each figure is worked out by hand from the probes' values.
TEST(PlanEstimates, ALocalStepEstimatesTheCutProbesToFirstOrderAndTheRestByExtrapolation) {
  geometry::SurfaceGrid grid =
      geometry::make_plane_grid("g", {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.0, 1.0, 0.5);
  ASSERT_EQ(grid.points.size(), 4u);
  const std::vector<size_t> probes = {0, 1, 2, 3};
  // Probe 0 was cut around, probes 1-3 were not. Their h, 2h, 4h differences fall as 2^-p with
  // p = 1.5 at probe 1 (the largest: it sets the order), less at the others.
  const std::vector<char> cut = {1, 0, 0, 0};
  const double q = std::exp2(1.5);
  const std::vector<double> h = {100.4, 100.0, 99.95, 100.02};
  const std::vector<double> h2 = {103.0, 100.8, 100.15, 99.92};
  const std::vector<double> h4 = {90.0, 100.8 + 0.8 * q, 100.35, 99.82};
  // E_ind(0) extrapolated at probe 1: 100 - 0.8 / (q - 1) = 99.5624 lx.
  const double e0 = 100.0 - 0.8 / (q - 1.0);
  const auto run = [&](double at_1, double at_0) {
    std::vector<double> E_ind = {at_0, at_1, 100.0, 100.0};  // all of E reflected
    return local_patch_error(grid, E_ind, E_ind, probes, cut, h, h2, h4);
  };
  // Probe 0 moved 0.4 lx by the step: 0.4 %. Probe 1 not moved: Richardson's estimate there,
  // 0.8 / (q - 1) = 0.4376 %, the larger (probes 2 and 3: 0.16 % and 0.07 %).
  PatchErrorEstimate r = run(100.0, 100.0);
  EXPECT_NEAR(r.error, (100.0 - e0) / 100.0, 1e-12);
  EXPECT_NEAR(r.order, 1.5, 1e-9);
  // Moved 0.3 lx towards the extrapolated value: 0.1376 lx of 99.7; probe 0's 0.4 % decides,
  // first order.
  r = run(99.7, 100.0);
  EXPECT_NEAR(r.error, 0.4 / 100.0, 1e-12);
  EXPECT_EQ(r.order, kMinPatchOrder);
  // Moved 0.3 lx away from it: 0.7376 lx of 100.3.
  r = run(100.3, 100.0);
  EXPECT_NEAR(r.error, (100.3 - e0) / 100.3, 1e-12);
  EXPECT_NEAR(r.order, 1.5, 1e-9);
  // Probe 0 moved further (0.6 lx the other way): its first-order figure decides. Its coarse
  // levels (103, 90: not in any order with h) play no part.
  r = run(100.0, 101.0);
  EXPECT_NEAR(r.error, 0.6 / 101.0, 1e-12);
  EXPECT_EQ(r.order, kMinPatchOrder);
}

// The probes a local step cuts around: those whose difference between h and 2h exceeds the
// threshold of their E, dark ones counted against 1 % of the largest E known.
TEST(PlanEstimates, LocalRefinementProbesAreThoseAboveTheThreshold) {
  const std::vector<double> E_direct = {400.0, 0.0, 100.0, 0.5, 0.0};
  const std::vector<size_t> probes = {0, 2, 3, 4};
  // E at the probes: 500, 200, 2.5 (floor: 1 % of 500 = 5 lx), 0 + 0 (no light: never).
  const std::vector<double> at_h = {100.0, 100.0, 2.0, 0.0};
  const std::vector<double> at_2h = {104.0, 102.1, 2.04, 0.0};
  // Differences: 4 / 500 = 0.8 %, 2.1 / 200 = 1.05 %, 0.04 / 5 = 0.8 %, 0.
  const std::vector<char> centre = local_refinement_probes(E_direct, probes, at_h, at_2h, 0.01);
  EXPECT_EQ(centre, (std::vector<char>{0, 1, 0, 0}));
  EXPECT_EQ(local_refinement_probes(E_direct, probes, at_h, at_2h, 0.005),
            (std::vector<char>{1, 1, 1, 0}));
}

TEST(PlanEstimates, PatchSizeEstimateIsNotBelowTheMeshErrorSeenAtHalfTheSize) {
  // The estimate at patch size h is |E_ind(h) - E_ind(2h)| (first-order convergence in h). The
  // mesh's true error at h is at least |E_ind(h) - E_ind(h / 2)| when the indirect light
  // converges monotonically in h (it is then half of it for first order, 3/4 for second), so an
  // estimate below that would miss error the mesh demonstrably has. Checked at the probe points
  // of the office at standard's nominal 0.5 m (h / 2 = 0.25 m, 1700 patches: about a second),
  // with the estimator the plan uses (patch_size_estimate), E_direct from the standard run.
  const Scene scene = office();
  const Results standard = run_scene(scene);
  const double mf = scene.settings.maintenance_factor;
  indirect::IndirectOptions options = indirect::indirect_options(scene.settings);
  options.visibility = standard.plan.visibility_test;
  std::vector<geometry::SurfaceGrid> probes;
  std::vector<std::vector<size_t>> picked;
  for (const auto& g : scene.surfaces) {
    picked.push_back(probe_points(g));
    probes.push_back(probe_grid(g, picked.back()));
  }
  const double h = 0.5;
  const auto at = [&](double size) {
    options.patch_size_m = size;
    return indirect::compute_indirect(scene, probes, options).E_indirect_per_surface;
  };
  const auto coarse = at(2 * h), mesh = at(h), fine = at(h / 2);
  for (size_t s = 0; s < standard.surfaces.size(); ++s) {
    const auto& r = standard.surfaces[s];
    // The surface's E and E_indirect at h, unmaintained (the estimator is a ratio), with the
    // probes' values in their places; the other points keep the standard run's, for the floor
    // of 1 % of the surface's maximum.
    std::vector<double> E(r.E.size()), E_ind(r.E.size());
    for (size_t i = 0; i < r.E.size(); ++i) E_ind[i] = r.E_indirect[i] / mf;
    for (size_t k = 0; k < picked[s].size(); ++k) E_ind[picked[s][k]] = mesh[s][k];
    for (size_t i = 0; i < r.E.size(); ++i) E[i] = r.E_direct[i] / mf + E_ind[i];
    const double estimate = patch_size_estimate(r.grid, E, E_ind, picked[s], coarse[s]);
    const double seen = patch_size_estimate(r.grid, E, E_ind, picked[s], fine[s]);
    std::printf("office %s: patch-size estimate %.3f %%, |E(h) - E(h/2)| %.3f %% (h = %.3g m)\n",
                r.grid.name.c_str(), 100 * estimate, 100 * seen, h);
    // Below a fifth of the promise the convergence is not monotone at every point (the desk
    // probes: 0.008 % against 0.02 %; the workplane, with near patches gathered cell by cell:
    // 0.102 % against 0.111 %); there the estimate must only stay below the promise, so that it
    // raises no warning the mesh does not deserve (activity plane: 0.23 %).
    if (seen > 0.2 * nearfield::kStandardPromise)
      EXPECT_GE(estimate, seen) << r.grid.name;
    else
      EXPECT_LT(estimate, nearfield::kStandardPromise) << r.grid.name;
  }
}

// The run's patch-size estimate on a small room against the error measured against the same
// room solved at a quarter of the patch size (h / 4) at the same probes. That solve has its own
// error, (1 / 4)^p of the run's for order p: the measured difference is between 3 / 4 (p = 1) and
// 15 / 16 (p = 2) of the run's true error, so an estimate within a factor of 2 of the truth is
// within [3 / 8, 8 / 3] of the measured difference; checked where the measured difference is
// above a tenth of the promise (below it, the estimate must only stay below the promise).
TEST(PlanEstimates, PatchSizeEstimateBracketsTheErrorAgainstAFinerSolve) {
  const std::string text = R"({"format": "luxgrid-project/1", "name": "small room",
    "settings": {"quality": "standard", "indirect": "on", "allow_files_outside_project": true},
    "photometry": {"p": ")" +
                           std::string(LUXGRID_SOURCE_DIR) +
                           R"(/examples/office/photometry/zumtobel_mirel_isym4.ldt"},
    "rooms": [{"name": "room", "outline": [[0, 0], [3.5, 0], [3.5, 3], [0, 3]], "height": 2.6,
               "reflectance": {"floor": 0.2, "walls": 0.5, "ceiling": 0.7}}],
    "luminaires": [{"name": "a", "photometry": "p", "position": [1.2, 1.5, 2.6]}],
    "surfaces": [{"name": "workplane", "workplane": {"room": "room", "height": 0.75,
                                                      "border": 0.25}, "spacing": 0.25},
                 {"name": "room", "room_surfaces": {"room": "room"}, "spacing": 0.25}]})";
  const Scene scene =
      project::parse_project_text(text, "small.json", std::string(LUXGRID_SOURCE_DIR)).scene;
  const Results run = run_scene(scene);
  ASSERT_TRUE(run.plan.indirect_run);
  const double h = run.plan.indirect_run->patch_size_m;
  const double mf = scene.settings.maintenance_factor;
  indirect::IndirectOptions options = indirect::indirect_options(scene.settings);
  options.visibility = run.plan.visibility_test;
  options.patch_size_m = h / 4;
  std::vector<geometry::SurfaceGrid> probes;
  std::vector<std::vector<size_t>> picked;
  for (size_t s = 0; s < scene.surfaces.size(); ++s) {
    // The run's probes: evenly spread, and where the direct light is weakest.
    picked.push_back(probe_points(scene.surfaces[s]));
    add_shadow_probes(scene.surfaces[s], run.surfaces[s].E_direct, picked.back());
    probes.push_back(probe_grid(scene.surfaces[s], picked.back()));
  }
  const auto fine = indirect::compute_indirect(scene, probes, options).E_indirect_per_surface;
  int checked = 0;
  for (size_t s = 0; s < run.surfaces.size(); ++s) {
    const SurfaceResult& r = run.surfaces[s];
    const double e_max = *std::max_element(r.E.begin(), r.E.end());
    double measured = 0.0;
    for (size_t k = 0; k < picked[s].size(); ++k) {
      const size_t i = picked[s][k];
      measured = std::max(
          measured, std::abs(r.E_indirect[i] - mf * fine[s][k]) / std::max(r.E[i], 0.01 * e_max));
    }
    const SurfaceEstimate& e = run.plan.estimates[s];
    std::printf(
        "%s: patch-size estimate %.3f %% (order %.2f, difference to 2h %.3f %%), against "
        "h / 4 %.3f %% (h = %.3g m)\n",
        r.grid.name.c_str(), 100 * e.patch_size, e.patch_order, 100 * e.patch_difference,
        100 * measured, h);
    if (measured > 0.1 * nearfield::kStandardPromise) {
      EXPECT_GE(e.patch_size, 3.0 / 8.0 * measured) << r.grid.name;
      EXPECT_LE(e.patch_size, 8.0 / 3.0 * measured) << r.grid.name;
      ++checked;
    } else {
      EXPECT_LT(e.patch_size, nearfield::kStandardPromise) << r.grid.name;
    }
  }
  EXPECT_GT(checked, 0);
}

TEST(PlanEstimates, BounceEstimateFollowsTheResidual) {
  // One bounce leaves out rho / (1 - rho) of the first bounce's flux (radiosity.h): the estimate
  // must see a large share, and the converged run a small one (its residual is below the
  // standard tolerance of 1e-3, times E_ind / E <= 1).
  Scene scene = office();
  const Results converged = run_scene(scene);
  scene.settings.bounces = 1;
  const Results one = run_scene(scene);
  for (size_t s = 0; s < one.surfaces.size(); ++s) {
    std::printf("office %s: bounce estimate converged %.4f %%, one bounce %.2f %%\n",
                one.surfaces[s].grid.name.c_str(), 100 * converged.plan.estimates[s].bounces,
                100 * one.plan.estimates[s].bounces);
    EXPECT_LE(converged.plan.estimates[s].bounces, 1e-3);
    // The true share one bounce misses: the converged E_ind less the one-bounce E_ind, the
    // largest over the surface. The estimate charges each point the residual times its own
    // first-bounce light, but the later bounces spread more evenly than the first: where the
    // first bounce is weak (desk probes, the activity plane) it reads up to 5 times low
    // (measured 1.6 % against 8.6 %). What it must do is see that one bounce breaks the promise
    // everywhere here, so the run warns, and not claim more than is missing.
    const auto& c = converged.surfaces[s];
    const auto& o = one.surfaces[s];
    double missing = 0.0;
    const double e_max = *std::max_element(c.E.begin(), c.E.end());
    for (size_t i = 0; i < c.E.size(); ++i)
      missing =
          std::max(missing, (c.E_indirect[i] - o.E_indirect[i]) / std::max(c.E[i], 0.01 * e_max));
    std::printf("  missing share measured %.2f %%\n", 100 * missing);
    EXPECT_GT(one.plan.estimates[s].bounces, nearfield::kStandardPromise);
    // At most 1.25 x the measured share: the flux-weighted mean reflectance of the first bounce
    // is above the room's effective one where the pale ceiling is lit most (ceiling: 62 % vs 53 %).
    EXPECT_LT(one.plan.estimates[s].bounces, 1.25 * missing);
  }
}

TEST(PlanEstimates, EstimateAbovePromiseIsAWarning) {
  // The office at standard with one bounce: the bounces not followed are tens of percent of the
  // indirect light, far above the 1 % promise; the plan says so per surface and warns.
  Scene scene = office();
  scene.settings.bounces = 1;
  const Results r = run_scene(scene);
  EXPECT_EQ(r.plan.promise, 0.01);
  EXPECT_TRUE(r.plan.errors_estimated);
  // The first surface's estimate is above the promise, the bounces its largest part (the words
  // of the warning: report/plan_text_test.cpp).
  ASSERT_FALSE(r.plan.estimates.empty());
  const SurfaceEstimate& e = r.plan.estimates.front();
  EXPECT_GT(e.total(), r.plan.promise);
  EXPECT_GT(e.bounces, std::max(e.direct, e.patch_size));
  // The patch size is not refined for it: the bounces, not the mesh, are what is missing.
  EXPECT_TRUE(r.plan.refinements.empty());
}

// `draft` solves one mesh and has nothing to compare it with: its patch-size estimate is absent
// (-1), not 0, while its bounces (one) are estimated.
TEST(PlanEstimates, DraftDoesNotClaimAPatchSizeEstimate) {
  Scene scene = office();
  scene.settings.quality = Quality::draft;
  const Results r = run_scene(scene);
  ASSERT_TRUE(r.plan.indirect_run.has_value());
  EXPECT_EQ(r.plan.indirect_run->coarse_patch_size_m, 0.0);
  ASSERT_FALSE(r.plan.estimates.empty());
  for (const SurfaceEstimate& e : r.plan.estimates) {
    EXPECT_EQ(e.patch_size, -1.0) << e.surface;
    EXPECT_GT(e.bounces, 0.0) << e.surface;
  }
}

// `reference`, the yardstick, halves its 0.2 m mesh once where its own patch-size difference is
// above half its convergence target (kReferenceConvergenceTarget, 0.2 %): the office's 0.2 m
// mesh differs from 0.4 m by up to 0.5 % (its ceiling), so it is solved at 0.1 m (10 400
// patches, the clustered transfer), where the estimate from 0.1, 0.2 and 0.4 m is within the
// target on every surface (measured: at most 0.105 %, the activity faces).
TEST(PlanEstimates, ReferenceHalvesItsMeshWhereItsOwnEstimateAsks) {
  Scene scene = office();
  scene.settings.quality = Quality::reference;
  const Results r = run_scene(scene);
  ASSERT_EQ(r.plan.refinements.size(), 1u);
  const PatchRefinement& step = r.plan.refinements.front();
  EXPECT_EQ(step.outcome, PatchRefinement::Outcome::refined);
  EXPECT_DOUBLE_EQ(step.from_m, 0.2);
  EXPECT_DOUBLE_EQ(step.to_m, 0.1);
  EXPECT_GT(step.estimate, kPatchShareOfPromise * kReferenceConvergenceTarget);
  ASSERT_TRUE(r.plan.indirect_run.has_value());
  EXPECT_DOUBLE_EQ(r.plan.indirect_run->patch_size_m, 0.1);
  EXPECT_DOUBLE_EQ(r.plan.indirect_run->coarse_patch_size_m, 0.2);
  EXPECT_DOUBLE_EQ(r.plan.indirect_run->coarser_patch_size_m, 0.4);
  for (const SurfaceEstimate& e : r.plan.estimates) {
    std::printf("office at reference, %s: patch-size estimate %.3f %%\n", e.surface.c_str(),
                100 * e.patch_size);
    EXPECT_LE(e.patch_size, kReferenceConvergenceTarget) << e.surface;
  }
  // The other qualities keep their promise as the target; draft refines nothing.
  EXPECT_EQ(refinement_target(Quality::standard), promised_error(Quality::standard));
  EXPECT_EQ(refinement_target(Quality::high), promised_error(Quality::high));
  EXPECT_EQ(refinement_target(Quality::draft), 0.0);
}

// A convex room clustered at standard's 0.5 m (5 600 m^2: 22 400 patches) has 5 600 patches at
// the estimate's 1 m: more than the dense budget of 4 000 and fewer than the clustered rooms'
// threshold. The estimate meshes it by the same method as the run it estimates, so the run
// neither fails on the dense budget nor compares the clustered transfer with a dense one.
TEST(PlanEstimates, AClusteredRoomIsEstimatedByTheClusteredTransfer) {
  const std::string text = R"({"format": "luxgrid-project/1", "name": "hall",
    "settings": {"quality": "standard", "indirect": "on", "allow_files_outside_project": true},
    "photometry": {"p": ")" +
                           std::string(LUXGRID_SOURCE_DIR) +
                           R"(/examples/office/photometry/zumtobel_mirel_isym4.ldt"},
    "rooms": [{"name": "hall", "outline": [[0, 0], [60, 0], [60, 40], [0, 40]], "height": 4,
               "reflectance": {"floor": 0.2, "walls": 0.5, "ceiling": 0.7}}],
    "luminaires": [{"name": "a", "photometry": "p", "position": [30, 20, 4]}],
    "surfaces": [{"name": "points", "points": [{"at": [30, 20, 0.75], "normal": [0, 0, 1]},
                                               {"at": [5, 5, 0.75], "normal": [0, 0, 1]}]}]})";
  const Scene scene =
      project::parse_project_text(text, "hall.json", std::string(LUXGRID_SOURCE_DIR)).scene;
  ASSERT_TRUE(indirect::use_clustered_transfer(scene.rooms[0], 0.5));
  ASSERT_FALSE(indirect::use_clustered_transfer(scene.rooms[0], 1.0));
  const Results r = run_scene(scene);
  ASSERT_TRUE(r.plan.indirect_run);
  EXPECT_EQ(r.plan.indirect_run->clustered_rooms, 1u);
  ASSERT_EQ(r.plan.estimates.size(), 1u);
  EXPECT_EQ(r.plan.estimates[0].probe_points, 2u);
  EXPECT_GE(r.plan.estimates[0].patch_size, 0.0);
  // Nor is the patch size raised for the budget.
  EXPECT_TRUE(r.plan.indirect_notes.empty());
}

}  // namespace
}  // namespace luxgrid::calc
