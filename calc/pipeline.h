#pragma once
// The whole calculation of a loaded scene: plan, direct, indirect, statistics, timings.
#include <memory>

#include "calc/direct.h"
#include "calc/indirect/indirect.h"
#include "calc/plan_estimates.h"
#include "calc/results.h"

namespace luxgrid::calc {

// Throws CalculationError naming the surface and the first point (index, position) or
// statistic that is not a finite number: results never hold NaN or infinities.
Results run_scene(const Scene& scene, const Progress& progress = {});

// What of the reflected light (calc/indirect) with `options` reads no direct light: the run's
// solution and, but at draft, the estimate's mesh of twice its patch size (only their gathers
// at the probes read the direct light), so that it can be solved beside the direct light.
struct ReflectedSolutions {
  std::unique_ptr<const indirect::IndirectSolution> run, coarse;
};
ReflectedSolutions solve_reflected_light(const Scene& scene,
                                         const indirect::IndirectOptions& options);

// Reflected light (calc/indirect) with `options`: solved, refined where the plan's patch-size
// estimate asks (plan_estimates.h; not at draft) and gathered at every point into each
// surface's E_indirect, with the plan's indirect run, notes and warnings. results.surfaces must
// hold the grids and E_direct. Returns what estimate_errors needs. The normal and emergency
// scenes call it with the luminaires' first bounce, the daylight scene with the light entering
// through the openings (IndirectOptions::incident_flux_lm). `solved`: solve_reflected_light(scene,
// options) when the caller has solved it already (empty: solved here). `direct`: the direct
// light's estimate, which the refinement's local step weighs (null: the step weighs the reflected
// light's parts alone).
IndirectEstimateInputs run_reflected_light(const Scene& scene,
                                           const indirect::IndirectOptions& options,
                                           Results& results, ReflectedSolutions solved = {},
                                           const DirectEstimateInputs* direct = nullptr);

}  // namespace luxgrid::calc
