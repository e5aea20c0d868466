#include "calc/pipeline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include <tbb/task_group.h>

#include "calc/daylight_run.h"
#include "calc/direct_reach.h"
#include "calc/glare/ugr.h"
#include "calc/indirect/clustered.h"
#include "calc/indirect/indirect.h"
#include "calc/indirect/patches.h"
#include "calc/indirect/subcells.h"
#include "calc/intensity_lookup.h"
#include "calc/plan_estimates.h"
#include "calc/scene_far_field_bounds.h"
#include "util/error.h"
#include "util/format.h"

namespace luxgrid::calc {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Direct light on every surface; progress runs from 0 to 1 over all points. Each point tests
// only the luminaires that can reach it (calc/direct_reach.h). Returns the plan's estimate of the
// direct light's error at each point (lx, initial values).
DirectEstimateInputs run_direct(const Scene& scene, const SceneLookups& lookups, Results& results,
                                const Progress& progress) {
  DirectEstimateInputs estimates;
  size_t total_points = 0;
  for (const auto& s : scene.surfaces) total_points += s.points.size();
  auto emitters = make_emitters(scene);
  DirectReach reach(scene, results.plan.visibility_test);
  std::vector<std::vector<uint32_t>> zones;
  for (const auto& grid : scene.surfaces) zones.push_back(reach.zones_of(grid));
  // The error-bound map measures the far-field model on the table; the texture's own deviation
  // (calc/intensity_lookup.h) is within a tenth of the promise on top of it. Each map measures
  // what the pairs below will ask of it.
  results.plan.near_far = attach_far_field_bounds(scene, results.plan, emitters, &reach, &zones);
  attach_intensity_lookups(lookups, emitters);
  DirectCounts counts;
  size_t points_before = 0;
  size_t pairs_unreachable = 0;
  for (size_t s = 0; s < scene.surfaces.size(); ++s) {
    const geometry::SurfaceGrid& grid = scene.surfaces[s];
    SurfaceResult r;
    r.grid = grid;
    Progress surface_progress;
    if (progress && total_points > 0) {
      const double share = static_cast<double>(grid.points.size()) / total_points;
      const double offset = static_cast<double>(points_before) / total_points;
      surface_progress = [=](double f) { progress(offset + share * f); };
    }
    const GridReach grid_reach{reach, std::move(zones[s])};
    estimates.error_lx.emplace_back();
    r.E_direct = direct_illuminance(results.plan, emitters, grid, surface_progress, &counts,
                                    &grid_reach, &estimates.error_lx.back());
    for (size_t i = 0; i < grid.points.size(); ++i) {
      if (grid.active.empty() || grid.active[i])
        pairs_unreachable +=
            emitters.size() - reach.zone(grid_reach.zone_of_point[i]).luminaires.size();
    }
    r.E_indirect.assign(r.E_direct.size(), 0.0);
    points_before += grid.points.size();
    results.surfaces.push_back(std::move(r));
  }
  results.plan.direct_counts = counts;
  results.plan.pairs_unreachable = pairs_unreachable;
  // The far field at every distance (near_field "never") has no map: its error is not estimated.
  const bool area =
      std::any_of(emitters.begin(), emitters.end(), [](const auto& e) { return !e.is_point(); });
  estimates.estimated = !(results.plan.near_switch == nearfield::NearFieldSwitch::never && area);
  results.plan.direct_estimated = estimates.estimated;
  return estimates;
}

// The patch size chosen by the estimate: while a surface's patch-size difference exceeds
// kPatchShareOfPromise of the quality's refinement target (plan_estimates.h: its promise, or
// `reference`'s convergence target), the rooms are meshed again at half the size, the run before
// becoming the coarse one of the estimate (so each step costs one run at the finer size), at most
// `steps` times, never beyond the patch budget (limits.h) and never beyond `work_limit`. The rest
// of the target is left to the direct light's and the bounces' estimates.
struct RefinementRule {
  int steps = 0;
  double work_limit = 0.0;  // pairs and links, as refine_work counts them
  // Whether a step over the work limit may cut the mesh around the probes instead (refine_locally).
  bool local = false;
};
// The work a finer mesh may cost: the form-factor pairs of its rooms (patches^2 per room, from
// the rooms' areas), a pair counting kVisibilityPairCost times where the room needs visibility
// tests (not convex, or with obstacles: each pair then traces rays). 1728 patches in the convex
// office at 0.25 m are 3 million pairs, a tenth of a second; the L-shaped example's 3072 patches
// at 0.25 m with visibility would be 75 million, tens of seconds. A room with the clustered
// transfer (calc/indirect/clustered.h) counts its links instead.
constexpr double kRefineWorkLimit = 1e7;
// `high` may spend three times that: its 0.3 % needs 0.125 m patches where something blocks light
// (examples/lshape, tests/rooms/ushape and tshape: 1.5 to 2.6 x 10^7 links at 0.125 m).
constexpr double kHighRefineWorkLimit = 3e7;
// `reference` halves its 0.2 m once where its own estimate asks for it, up to 5 x 10^7 links: a
// 0.1 m mesh of about 400 m^2 of surface, as tests/rooms/ushape and tshape (36 566 and 35 028
// patches, about a minute on two cores, tests/rooms/README.md); a hall beyond it stays at 0.2 m
// and says so. Once: a second step would cost four times as much again (examples/lshape at
// 0.05 m: 82 436 patches and 3.3 GB).
constexpr double kReferenceRefineWorkLimit = 5e7;
RefinementRule refinement_rule(Quality q) {
  switch (q) {
    case Quality::draft: return {};
    // Only `standard` takes the local step. At `high` (0.125 m in the test rooms) it was measured
    // and not kept: on tests/rooms/tshape it cut around walls 3 and 7, whose estimates fell from
    // 0.53 % and 0.58 % to 0.24 % and 0.08 %, but wall 4's point beside the 5 cm gap moved from
    // 0.075 % to 0.31 % from the stored reference (0.14 % to 0.25 % from one at 0.07 m), the wall
    // then warned at 0.59 %, and the run took 175 s of CPU instead of 96 s.
    case Quality::standard: return {2, kRefineWorkLimit, true};
    case Quality::high: return {2, kHighRefineWorkLimit};
    case Quality::reference: return {1, kReferenceRefineWorkLimit};
  }
  return {};
}
constexpr double kVisibilityPairCost = 8.0;
// `growth`: the patches of a mesh cut finer in places, as a multiple of the mesh's at patch_size_m.
double refine_work(const Scene& scene, double patch_size_m, double growth = 1.0) {
  double work = 0.0;
  for (const auto& room : scene.rooms) {
    const double n = growth * indirect::room_surface_area(room) / (patch_size_m * patch_size_m);
    if (indirect::use_clustered_transfer(room, patch_size_m)) {
      // A room with the clustered transfer: its links, not n^2 pairs.
      work += n * indirect::kClusteredLinksPerPatch;
      continue;
    }
    const bool traced = !indirect::outline_is_convex(room) || !room.obstacles.empty();
    work += n * n * (traced ? kVisibilityPairCost : 1.0);
  }
  return work;
}
// An upper bound of the reflected light anywhere in the solution's rooms, for the estimate's
// floor (plan_estimates.h): a point gathers at most the largest exitance it sees over a
// hemisphere (E = integral of L cos over the solid angle <= pi L_max = M_max, form factors
// summing to at most 1). Cells (subcells.h) may be brighter than their patch's mean and the far
// kernel is not exact, hence the margin.
constexpr double kIndirectBoundMargin = 8.0;
double indirect_upper_bound_lx(const indirect::IndirectSolution& solution) {
  double m_max = 0.0;
  for (size_t i = 0; i < solution.mesh.patches.size(); ++i) {
    const double area = solution.mesh.patches[i].area_m2;
    if (area > 0.0) m_max = std::max(m_max, solution.exitant_flux_lm[i] / area);
  }
  return kIndirectBoundMargin * m_max;
}

// The worst patch-size difference d1 over the surfaces for a solution at the evenly spread probes
// (the choice's, plan_estimates.h), the surface it is on and each surface's E_indirect at all
// its probes. Gathered at the probe points only (their values are the whole grid's there,
// indirect.h); a surface where the estimate's floor may decide the largest figure (a dark probe,
// see patch_size_estimate_at_probes) at every point of it alone, since the floor needs the
// surface's largest E. `everywhere`: the solution's results at every point, where gathered
// (`final`).
struct WorstPatchEstimate {
  double worst = 0.0;
  std::string surface;
  std::vector<std::vector<double>> probe_lx;
  std::optional<indirect::IndirectResult> everywhere;
};
// `final`: no finer mesh can follow (its work would exceed the rule's limit), so this solution
// gives the results whatever the estimate says: it is gathered at every point at once and the
// probes read from that (the same bits as gathering them alone), instead of gathering the
// probes twice.
WorstPatchEstimate worst_patch_estimate(const Scene& scene, const Results& results,
                                        const indirect::IndirectSolution& solution,
                                        const std::vector<geometry::SurfaceGrid>& probes,
                                        const IndirectEstimateInputs& est, bool final) {
  WorstPatchEstimate w;
  if (final) {
    w.everywhere = indirect::gather_indirect(solution, scene, scene.surfaces);
    for (size_t s = 0; s < probes.size(); ++s) {
      std::vector<double> at_probes;
      for (size_t i : est.probe_index[s])
        at_probes.push_back(w.everywhere->E_indirect_per_surface[s][i]);
      w.probe_lx.push_back(std::move(at_probes));
    }
  } else {
    w.probe_lx = indirect::gather_indirect(solution, scene, probes).E_indirect_per_surface;
  }
  const double bound_lx = indirect_upper_bound_lx(solution);
  const auto spread = [&]<typename T>(size_t s, const std::vector<T>& v) {
    return std::vector(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(est.spread_probes[s]));
  };
  std::vector<ProbeFigure> estimate;
  double worst_exact = 0.0;
  for (size_t s = 0; s < results.surfaces.size(); ++s) {
    estimate.push_back(patch_size_estimate_at_probes(
        results.surfaces[s].grid, results.surfaces[s].E_direct, spread(s, est.probe_index[s]),
        spread(s, w.probe_lx[s]), spread(s, est.coarse_lx[s]), bound_lx));
    if (estimate.back().exact) worst_exact = std::max(worst_exact, estimate.back().figure);
  }
  // A surface whose figure the probes only bound, where the bound reaches the largest exact
  // figure: at every point of it alone. A point's reflected light is the same whichever other
  // points are gathered with it (indirect.h), so its figure is that of a gather at every point of
  // the scene; one whose bound stays below cannot be the largest, so the largest and its surface
  // are those of the exact figures, to the bit. The everywhere gather of a `final` solution has
  // every point already.
  std::vector<size_t> needed;
  for (size_t s = 0; s < estimate.size(); ++s)
    if (!estimate[s].exact && !(estimate[s].figure < worst_exact)) needed.push_back(s);
  if (!needed.empty()) {
    std::vector<geometry::SurfaceGrid> grids;
    for (size_t s : needed) grids.push_back(scene.surfaces[s]);
    std::optional<indirect::IndirectResult> part;
    if (!w.everywhere) part = indirect::gather_indirect(solution, scene, grids);
    for (size_t k = 0; k < needed.size(); ++k) {
      const size_t s = needed[k];
      const SurfaceResult& sr = results.surfaces[s];
      const std::vector<double>& E_ind =
          w.everywhere ? w.everywhere->E_indirect_per_surface[s] : part->E_indirect_per_surface[k];
      std::vector<double> E(sr.E_direct.size());
      for (size_t i = 0; i < E.size(); ++i) E[i] = sr.E_direct[i] + E_ind[i];
      estimate[s] = {patch_size_estimate(sr.grid, E, E_ind, spread(s, est.probe_index[s]),
                                         spread(s, est.coarse_lx[s])),
                     true};
    }
  }
  for (size_t s = 0; s < results.surfaces.size(); ++s)
    if (estimate[s].exact && estimate[s].figure > w.worst)
      w.worst = estimate[s].figure, w.surface = results.surfaces[s].grid.name;
  return w;
}

// The estimate's mesh of twice the run's patch size: each room by the same method as the run it
// estimates.
indirect::IndirectOptions coarse_options(const indirect::IndirectOptions& options,
                                         const indirect::IndirectSolution& run) {
  indirect::IndirectOptions coarse = options;
  coarse.patch_size_m = 2.0 * run.result.patch_size_m;
  coarse.clustered = run.result.clustered;
  return coarse;
}

// The local step (plan_estimates.h, kLocalRefinementReach): where the mesh at half the size
// would cost more than the rule allows and the plan's estimate of the mesh as it is (every part,
// as estimate_errors states it) exceeds the target on a surface, the patches within
// kLocalRefinementReach patch sizes of that surface's probes whose difference d1 is above
// kPatchShareOfPromise of the target are cut into quarters and the rooms solved again at the same
// patch size. A surface within the target is left alone: the step costs a solve of the whole mesh,
// and the refinement's own test (d1 against half the target) asks for more than the promise needs.
// Returns false, changing nothing but the 4h level it may add to `est`, where no surface or no
// probe asks for it or where the cut mesh's work (refine_work's, grown by the patches it adds)
// would itself exceed the limit. On success `solution` is the cut mesh's, `est` holds the levels
// the estimate needs (the run before as h, its 2h and 4h) and `step` says what was cut.
// `everywhere`: the solution's reflected light at every point; `direct`: the direct light's
// estimate (null: not estimated).
bool refine_locally(const Scene& scene, const RefinementRule& rule,
                    const indirect::IndirectOptions& options,
                    std::unique_ptr<const indirect::IndirectSolution>& solution,
                    const std::vector<geometry::SurfaceGrid>& probes,
                    std::vector<std::vector<double>>& probe_lx,
                    const indirect::IndirectResult& everywhere, const DirectEstimateInputs* direct,
                    Results& results, IndirectEstimateInputs& est, PatchRefinement& step) {
  const double size_m = solution->result.patch_size_m;
  const double target = refinement_target(scene.settings.quality);
  if (est.coarser_lx.empty()) {
    // The 4h level, for the estimate below (run_reflected_light would run it next otherwise).
    indirect::IndirectOptions c4 = coarse_options(options, *solution);
    c4.patch_size_m = 2.0 * est.coarse_patch_size_m;
    const indirect::IndirectResult r = indirect::compute_indirect(scene, probes, c4);
    est.coarser_patch_size_m = r.patch_size_m;
    est.coarser_lx = r.E_indirect_per_surface;
  }
  // The estimate as the run would state it with this mesh, on the initial values.
  IndirectEstimateInputs now = est;
  now.ran = true;
  now.residual = solution->result.residual;
  const DirectEstimateInputs not_estimated{false, {}};
  const double reach_m = kLocalRefinementReach * size_m;
  indirect::IndirectOptions local = options;
  local.patch_size_m = size_m;
  std::vector<std::vector<char>> centre(probes.size());
  for (size_t s = 0; s < probes.size(); ++s) {
    const SurfaceResult& r = results.surfaces[s];
    const std::vector<double>& E_ind = everywhere.E_indirect_per_surface[s];
    std::vector<double> E(E_ind.size());
    for (size_t i = 0; i < E.size(); ++i) E[i] = r.E_direct[i] + E_ind[i];
    const SurfaceEstimate e =
        estimate_surface(r.grid, E, E_ind, direct ? *direct : not_estimated, now, s);
    centre[s].assign(est.probe_index[s].size(), 0);
    if (!(e.total() > target)) continue;
    centre[s] = local_refinement_probes(r.E_direct, est.probe_index[s], probe_lx[s],
                                        est.coarse_lx[s], kPatchShareOfPromise * target);
    for (size_t k = 0; k < centre[s].size(); ++k)
      if (centre[s][k]) local.refine_near.push_back({probes[s].points[k], reach_m});
  }
  if (local.refine_near.empty()) return false;
  // The work of the cut mesh: each patch within reach of a centre becomes four.
  const indirect::PatchMesh& mesh = solution->mesh;
  size_t cut = 0;
  for (const indirect::Patch& p : mesh.patches)
    if (p.has_quarters && indirect::near_any(p, local.refine_near)) ++cut;
  const double growth =
      static_cast<double>(mesh.patches.size() + 3 * cut) / static_cast<double>(mesh.patches.size());
  if (refine_work(scene, size_m, growth) > rule.work_limit) return false;
  std::unique_ptr<const indirect::IndirectSolution> finer;
  try {
    finer = indirect::solve_indirect(scene, local);
  } catch (const InputError&) {
    return false;  // the cut mesh is over the patch budget: the mesh stays as it was
  }
  step.outcome = PatchRefinement::Outcome::local;
  step.to_m = 0.5 * size_m;
  step.local_points = local.refine_near.size();
  step.reach_m = reach_m;
  step.patches_cut = finer->result.locally_refined_patches;
  // The levels: the run before is h, its 2h and 4h the estimate's coarser two.
  est.coarsest_lx = std::move(est.coarser_lx);
  est.coarser_lx = std::move(est.coarse_lx);
  est.coarser_patch_size_m = est.coarse_patch_size_m;
  est.coarse_lx = std::move(probe_lx);
  est.coarse_patch_size_m = size_m;
  est.local_probe = std::move(centre);
  solution = std::move(finer);
  return true;
}

// Replaces `solution` by the finer ones it chooses; `gathered` gets the last solution's results
// at every point where the estimate needed them.
void refine_patch_size(const Scene& scene, Results& results, indirect::IndirectOptions options,
                       std::unique_ptr<const indirect::IndirectSolution>& solution,
                       const std::vector<geometry::SurfaceGrid>& probes,
                       IndirectEstimateInputs& est, const DirectEstimateInputs* direct,
                       std::optional<indirect::IndirectResult>& gathered) {
  const double target = refinement_target(scene.settings.quality);
  const RefinementRule rule = refinement_rule(scene.settings.quality);
  // Not when the bounces not followed already exceed the target (a fixed bounce count): a finer
  // mesh cannot make up for them.
  if (!(target > 0.0) || solution->result.residual > target) return;
  for (int step = 0; step < rule.steps; ++step) {
    const bool final = refine_work(scene, 0.5 * solution->result.patch_size_m) > rule.work_limit;
    WorstPatchEstimate w = worst_patch_estimate(scene, results, *solution, probes, est, final);
    gathered = std::move(w.everywhere);
    if (!(w.worst > kPatchShareOfPromise * target)) return;
    const double size_m = solution->result.patch_size_m;
    PatchRefinement step_taken;
    step_taken.from_m = size_m;
    step_taken.estimate = w.worst;
    step_taken.surface = w.surface;
    options.patch_size_m = 0.5 * size_m;
    step_taken.to_m = options.patch_size_m;
    const double work = refine_work(scene, options.patch_size_m);
    if (work > rule.work_limit) {
      step_taken.work_pairs = work;
      step_taken.work_limit_pairs = rule.work_limit;
      if (rule.local && gathered &&
          refine_locally(scene, rule, options, solution, probes, w.probe_lx, *gathered, direct,
                         results, est, step_taken)) {
        gathered.reset();
      } else {
        step_taken.outcome = PatchRefinement::Outcome::work_over_limit;
      }
      results.plan.refinements.push_back(std::move(step_taken));
      return;
    }
    std::unique_ptr<const indirect::IndirectSolution> finer;
    try {
      finer = indirect::solve_indirect(scene, options);
    } catch (const InputError& e) {
      // The finer mesh is over the patch budget (checked before anything is meshed).
      step_taken.outcome = PatchRefinement::Outcome::over_budget;
      step_taken.budget_error = e.what();
      results.plan.refinements.push_back(std::move(step_taken));
      return;
    }
    // The meshes before become the estimate's 2h and 4h (plan_estimates.h).
    est.coarser_lx = std::move(est.coarse_lx);
    est.coarser_patch_size_m = est.coarse_patch_size_m;
    est.coarse_lx = std::move(w.probe_lx);
    est.coarse_patch_size_m = size_m;
    step_taken.to_m = finer->result.patch_size_m;
    results.plan.refinements.push_back(std::move(step_taken));
    solution = std::move(finer);
    gathered.reset();
  }
}

// The reflected light of the luminaires' first bounce, as the plan decided it.
indirect::IndirectOptions luminaire_reflected_light(const Scene& scene, const SceneLookups& lookups,
                                                    const Plan& plan) {
  indirect::IndirectOptions options = indirect::indirect_options(scene.settings);
  options.luminous_flux_lm = plan.indirect_decision.luminous_flux_lm;
  options.visibility = plan.visibility_test;
  for (const auto& [distribution, lookup] : lookups.by_distribution)
    options.intensity_lookup.emplace(distribution, lookup.lookup);
  return options;
}

}  // namespace

ReflectedSolutions solve_reflected_light(const Scene& scene,
                                         const indirect::IndirectOptions& options) {
  ReflectedSolutions solved;
  solved.run = indirect::solve_indirect(scene, options);
  if (scene.settings.quality != Quality::draft)
    solved.coarse = indirect::solve_indirect(scene, coarse_options(options, *solved.run));
  return solved;
}

IndirectEstimateInputs run_reflected_light(const Scene& scene,
                                           const indirect::IndirectOptions& options,
                                           Results& results, ReflectedSolutions solved,
                                           const DirectEstimateInputs* direct) {
  IndirectEstimateInputs est;
  // Solved once per mesh; gathered at every point only for the mesh that gives the results (the
  // estimate's meshes are gathered at its probe points).
  if (!solved.run) solved = solve_reflected_light(scene, options);
  std::unique_ptr<const indirect::IndirectSolution> solution = std::move(solved.run);
  std::optional<indirect::IndirectResult> gathered;  // at every point, where already done
  est.ran = true;
  if (scene.settings.quality != Quality::draft) {
    std::vector<geometry::SurfaceGrid> probes;
    for (size_t s = 0; s < scene.surfaces.size(); ++s) {
      const geometry::SurfaceGrid& grid = scene.surfaces[s];
      est.probe_index.push_back(probe_points(grid));
      est.spread_probes.push_back(est.probe_index.back().size());
      add_shadow_probes(grid, results.surfaces[s].E_direct, est.probe_index.back());
      probes.push_back(probe_grid(grid, est.probe_index.back()));
    }
    indirect::IndirectOptions coarse = coarse_options(options, *solution);
    if (!solved.coarse) solved.coarse = indirect::solve_indirect(scene, coarse);
    const indirect::IndirectResult c = indirect::gather_indirect(*solved.coarse, scene, probes);
    solved.coarse.reset();
    est.coarse_patch_size_m = c.patch_size_m;
    est.coarse_lx = c.E_indirect_per_surface;
    refine_patch_size(scene, results, options, solution, probes, est, direct, gathered);
    // The estimate's 4h level where no refinement left one: a sixteenth of the patches. After a
    // local step the run's own size is h, and the level is that of the probes it did not cut
    // around (plan_estimates.h).
    const bool local = !est.local_probe.empty();
    if (local ? est.coarsest_lx.empty() : est.coarser_lx.empty()) {
      coarse.patch_size_m = 2.0 * (local ? est.coarser_patch_size_m : est.coarse_patch_size_m);
      coarse.clustered = solution->result.clustered;
      const indirect::IndirectResult c4 = indirect::compute_indirect(scene, probes, coarse);
      if (local) {
        est.coarsest_lx = c4.E_indirect_per_surface;
      } else {
        est.coarser_patch_size_m = c4.patch_size_m;
        est.coarser_lx = c4.E_indirect_per_surface;
      }
    }
  }
  const indirect::IndirectResult r =
      gathered ? std::move(*gathered) : indirect::gather_indirect(*solution, scene, scene.surfaces);
  for (size_t k = 0; k < results.surfaces.size(); ++k)
    results.surfaces[k].E_indirect = r.E_indirect_per_surface[k];
  IndirectRunPlan run;
  run.bounces_asked = r.bounces_asked;
  run.bounces_run = r.bounces_run;
  run.tail_added = r.tail_added;
  run.patches = r.patches;
  run.patch_size_m = r.patch_size_m;
  run.vpls = r.vpls;
  run.residual = r.residual;
  run.refined_patches = r.refined_patches;
  run.split_patches = r.split_patches;
  run.subcell_reach = indirect::kSubcellReach;
  run.subcells_per_side = indirect::kSubcellsPerSide;
  run.received_flux_lm = r.received_flux_lm;
  run.emitted_flux_lm = r.emitted_flux_lm;
  run.luminaire_flux_lm = r.luminaire_flux_lm;
  run.part_outside = r.part_outside;
  run.clustered_rooms = r.clustered_rooms;
  run.clustered_links = r.clustered_links;
  run.visibility = r.visibility;
  run.obstacles = r.obstacles;
  results.plan.indirect_run = run;
  results.plan.indirect_notes = r.notes;
  results.plan.indirect_warnings = r.warnings;
  est.residual = r.residual;
  est.patch_size_m = r.patch_size_m;
  est.escaped_flux_lm = r.escaped_flux_lm;
  return est;
}

namespace {
// "1.8e+308" / "inf" / "nan", for the messages below.
std::string number(double v) { return format_double("%.4g", v); }

// Results never hold NaN or an infinity (a photometric file with absurd candela values, an
// overflow in a sum): a written number that is not a number would be read as an answer. Throws
// CalculationError naming the surface and the first bad point (index and position) or
// statistic, so nothing is written.
void check_finite(const SurfaceResult& r) {
  const std::string surface = "surface '" + r.grid.name + "': ";
  for (size_t i = 0; i < r.E.size(); ++i) {
    if (std::isfinite(r.E_direct[i]) && std::isfinite(r.E_indirect[i]) && std::isfinite(r.E[i]))
      continue;
    const Vec3 p = i < r.grid.points.size() ? r.grid.points[i] : Vec3(0.0);
    throw CalculationError(surface + "the illuminance at point " + std::to_string(i) + " (" +
                           number(p.x) + ", " + number(p.y) + ", " + number(p.z) +
                           ") m is not a finite number (E_direct " + number(r.E_direct[i]) +
                           " lx, E_indirect " + number(r.E_indirect[i]) + " lx, E " +
                           number(r.E[i]) + " lx); the results are not written");
  }
  const std::pair<const char*, double> stats[] = {{"Emin", r.stats.Emin},
                                                  {"Eavg", r.stats.Eavg},
                                                  {"Emax", r.stats.Emax},
                                                  {"U0", r.stats.U0},
                                                  {"Ud", r.stats.Ud}};
  for (const auto& [name, value] : stats)
    if (!std::isfinite(value))
      throw CalculationError(
          surface + name + " is " + number(value) +
          " (the point values are finite but too large to sum); the results are not written");
}
}  // namespace

Results run_scene(const Scene& scene, const Progress& progress) {
  if (scene.settings.scene == LightingScene::daylight) return run_daylight_scene(scene, progress);
  Results results;
  results.project = scene.name;
  results.plan = make_plan(scene);
  results.scene = scene.settings.scene;

  // The intensity lookups of the far field and the first bounce, once per distribution (a
  // texture is built and measured against its table here: its own phase in timing.json).
  const auto t_lookup = std::chrono::steady_clock::now();
  const SceneLookups lookups = choose_intensity_lookups(scene);
  results.plan.intensity_lookups = lookups.plan;
  results.timing_s.emplace_back("intensity_lookup", seconds_since(t_lookup));

  // The reflected light's solutions read nothing of the direct light (only the estimate's gather
  // does, at the shadow probes): they are solved beside the direct light, each filling the
  // threads the other leaves idle. The same bits either way: no part's result depends on the
  // schedule.
  std::optional<indirect::IndirectOptions> reflected;
  if (results.plan.indirect_decision.run)
    reflected = luminaire_reflected_light(scene, lookups, results.plan);
  ReflectedSolutions solved;
  double solve_s = 0.0;
  auto solved_at = std::chrono::steady_clock::now();
  tbb::task_group beside;
  if (reflected)
    beside.run([&] {
      const auto t_solve = std::chrono::steady_clock::now();
      solved = solve_reflected_light(scene, *reflected);
      solved_at = std::chrono::steady_clock::now();
      solve_s = std::chrono::duration<double>(solved_at - t_solve).count();
    });
  const auto t_direct = std::chrono::steady_clock::now();
  DirectEstimateInputs direct_estimate;
  try {
    direct_estimate = run_direct(scene, lookups, results, progress);
  } catch (...) {
    // The direct light's error is the one reported, as when the solve came after it.
    beside.cancel();
    try {
      beside.wait();
    } catch (...) {
    }
    throw;
  }
  results.timing_s.emplace_back("direct", seconds_since(t_direct));

  // The reflected light's phase: its solve's own wall time (beside the direct light) and the rest.
  beside.wait();
  const auto t_rest = std::max(std::chrono::steady_clock::now(), solved_at);
  IndirectEstimateInputs indirect_estimate;
  if (reflected)
    indirect_estimate =
        run_reflected_light(scene, *reflected, results, std::move(solved), &direct_estimate);
  if (scene.settings.scene == LightingScene::emergency) {
    // Not the project's "indirect" setting: the emergency scene switches reflections off [EN1838].
    results.plan.emergency_direct_only = true;
  }
  results.timing_s.emplace_back("indirect", solve_s + seconds_since(t_rest));

  // Glare at observers, from the initial values (UGR, like CIE 190's tables, carries no
  // maintenance factor; docs/glare.md).
  for (auto& r : results.surfaces) {
    if (r.grid.kind != geometry::SurfaceGrid::Kind::observers) continue;
    // The loader refuses "indirect": "off" with observers; a scene built in code may still skip it.
    if (scene.settings.indirect == IndirectMode::off) {
      throw CalculationError("surface '" + r.grid.name +
                             "': UGR needs reflected light for the background "
                             "luminance, but the indirect calculation did not run (indirect is "
                             "off in the settings)");
    }
    r.observers = glare::evaluate_observers(scene, results.plan, r.grid, r.E_indirect);
    r.UGR_max = glare::max_ugr(r.observers);
  }

  // The maintenance factor applies to both parts [EN12464-1], so the parts add up to E.
  const double mf = scene.settings.maintenance_factor;
  results.quality = scene.settings.quality;
  results.maintenance_factor = mf;
  for (auto& r : results.surfaces) {
    r.E.resize(r.E_direct.size());
    for (size_t i = 0; i < r.E.size(); ++i) {
      r.E_direct[i] *= mf;
      r.E_indirect[i] *= mf;
      r.E[i] = r.E_direct[i] + r.E_indirect[i];
    }
    r.stats = compute_statistics(r.E, r.grid.active);
    check_finite(r);
  }
  for (auto* part : {&indirect_estimate.coarse_lx, &indirect_estimate.coarser_lx,
                     &indirect_estimate.coarsest_lx, &direct_estimate.error_lx})
    for (auto& surface : *part)
      for (double& e : surface) e *= mf;
  estimate_errors(results, direct_estimate, indirect_estimate);
  return results;
}

}  // namespace luxgrid::calc
