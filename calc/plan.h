#pragma once
// The plan: which effects this scene needs, which model computes each, and why. Every decision is
// a value (a model, counts, distances, estimates, the reason as a code with its numbers), so
// results say what was simulated; report/plan_text.h turns the plan into words for the terminal,
// report.html and results.json's summary, and results.json keeps the values themselves.
#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "calc/daylight_plan.h"
#include "calc/indirect/decision.h"
#include "calc/indirect/indirect_notes.h"
#include "calc/intensity_lookup.h"
#include "calc/near_model_name.h"
#include "calc/nearfield/far_field_bound.h"
#include "calc/nearfield/illuminance.h"
#include "calc/scene.h"
#include "calc/scene_visibility.h"

namespace luxgrid::calc {

// The plan's estimate of its own error at one surface (calc/plan_estimates.h): each remaining
// approximation's share, relative to max(E, 1 % of the surface's maximum) at each point as
// `luxgrid cost` measures, the largest over the surface's points. The indirect shares are negative
// when reflected light was not computed (nothing to estimate).
struct SurfaceEstimate {
  std::string surface;
  double direct = 0.0;       // far field and fixed rule where pairs use them: the map's measurement
  double patch_size = -1.0;  // interreflection mesh: Richardson's with the order measured
  double patch_difference = -1.0;  // |E_ind(h) - E_ind(2h)| / E, the largest on probe points
  double patch_order = -1.0;       // the order patch_size extrapolated with (plan_estimates.h)
  double bounces = -1.0;           // bounces not followed: the radiosity residual x E_ind / E
  size_t probe_points = 0;         // points the patch-size estimate was measured at
  double total() const {
    return std::max(direct, 0.0) + std::max(patch_size, 0.0) + std::max(bounces, 0.0);
  }
};

// How many luminaire-point pairs each direct model served (filled by calc/direct).
struct DirectCounts {
  size_t point_sources = 0;  // luminaires without an opening: the point model is exact
  size_t far = 0;            // area emitters beyond the five-times band
  size_t near = 0;           // area emitters inside it
  size_t blended = 0;        // within the blend band: both, weighted
  size_t fixed_rule = 0;     // of `near`: by the fixed rule alone (nearfield/fixed_rule.h)
  size_t fixed_blended = 0;  // of `near` and `blended`: the fixed rule blended into the near rung
  DirectCounts& operator+=(const DirectCounts& o) {
    point_sources += o.point_sources;
    fixed_rule += o.fixed_rule;
    fixed_blended += o.fixed_blended;
    far += o.far;
    near += o.near;
    blended += o.blended;
    return *this;
  }
};

// Why the near/far switch is what it is.
enum class NearSwitchReason {
  draft_quality,      // draft (without a near_field_model): the far field at every distance
  setting_never,      // settings.near_field "never"
  setting_always,     // settings.near_field "always"
  reference_quality,  // reference (without a near_field_model): the near field everywhere
  automatic,          // by the error-bound map, or by the five-times rule without one
};

// The near/far map of one distinct emitter (calc/scene_far_field_bounds.h).
struct NearFarPlan {
  LuminaireGroup group;
  nearfield::FarFieldBoundSummary bound;
};

// What reflected light's solve did, when it ran (calc/indirect/indirect.h).
struct IndirectRunPlan {
  int bounces_asked = 0;  // 1: one bounce; > 1 that many; 0: converged
  int bounces_run = 0;
  bool tail_added = false;
  size_t patches = 0;
  double patch_size_m = 0.0;
  size_t vpls = 0;
  double residual = 0.0;
  size_t refined_patches = 0;  // cut into subcells_per_side^2 cells, seen closer than subcell_reach
  size_t split_patches = 0;    // cut into quarters where the light jumps (indirect/split_mask.h)
  double subcell_reach = 0.0;  // patch diameters
  int subcells_per_side = 0;
  double received_flux_lm = 0.0, emitted_flux_lm = 0.0, luminaire_flux_lm = 0.0;
  bool part_outside = false;  // the openings send a share of their flux outside every room
  size_t clustered_rooms = 0, clustered_links = 0;
  bool visibility = false;  // an AABB tree of room and obstacle faces
  size_t obstacles = 0;
  // The plan's estimate of the run's error (calc/plan_estimates.h), when measured.
  bool estimated = false;
  double coarse_patch_size_m = 0.0, coarser_patch_size_m = 0.0;
  size_t probe_points_per_surface = 0;
  double worst_patch_size = 0.0, worst_bounces = 0.0;  // relative, over the surfaces
};

// One step of the patch-size refinement (calc/pipeline.cpp): the estimate at `from_m` was above
// half the promise on `surface`; the mesh became `to_m`, or was cut to `to_m` only around
// `local_points` probe points (`local`: the whole mesh at `to_m` would cost `work_pairs`), or
// stayed for a reason.
struct PatchRefinement {
  enum class Outcome { refined, work_over_limit, over_budget, local };
  Outcome outcome = Outcome::refined;
  double from_m = 0.0, to_m = 0.0;
  double estimate = 0.0;  // relative
  std::string surface;
  double work_pairs = 0.0, work_limit_pairs = 0.0;  // work_over_limit, local
  std::string budget_error;                         // over_budget: the solver's refusal
  // local: the probes cut around, how far around them (m) and how many patches were quartered
  size_t local_points = 0;
  double reach_m = 0.0;
  size_t patches_cut = 0;
};

struct Plan {
  Quality quality = Quality::standard;
  // Direct light: the near-field rung for area emitters and how the near/far switch is made.
  nearfield::Model near_model = nearfield::Model::standard();
  nearfield::NearFieldSwitch near_switch = nearfield::NearFieldSwitch::automatic;
  NearSwitchReason near_switch_reason = NearSwitchReason::automatic;
  // Occlusion test, or null when nothing in the scene can block light (calc/scene_visibility.h).
  std::shared_ptr<const geometry::Visibility> visibility_test;
  VisibilityDecision visibility;
  // What the direct calculation counted, once it ran.
  DirectCounts direct_counts;
  size_t pairs_unreachable = 0;  // the opening in none of the point's rooms
  // Per distinct emitter, the near-field distances the error bound chose and why; empty when the
  // switch is not automatic or no luminaire has an opening.
  std::vector<NearFarPlan> near_far;
  // Per distinct distribution, what far-field pairs and the first bounce look intensities up in.
  std::vector<IntensityLookupPlan> intensity_lookups;
  // Reflected light: whether it runs and why (calc/indirect/decision.h), what the run did.
  indirect::IndirectDecision indirect_decision;
  std::optional<IndirectRunPlan> indirect_run;
  bool emergency_direct_only = false;  // the emergency scene counts direct light only [EN1838]
  std::vector<PatchRefinement> refinements;
  // The scene's notes (the emergency scene's choices, calc/scene_notes.h).
  std::vector<SceneNote> scene_notes;
  // What reflected light's solver noted and warned (calc/indirect/indirect_notes.h).
  std::vector<indirect::IndirectNote> indirect_notes, indirect_warnings;
  // What the quality promises (relative, 0: no number) and the plan's own error estimate per
  // surface (calc/plan_estimates.h), filled once the illuminance is known.
  double promise = 0.0;
  bool direct_estimated = true;   // false: the far field at every distance, no map
  bool errors_estimated = false;  // estimate_errors ran (the estimates below are the run's)
  std::vector<SurfaceEstimate> estimates;  // one per surface, in the surfaces' order
  // The daylight scene's choices (calc/daylight_run.h); none in the other scenes.
  std::optional<DaylightPlan> daylight;
};

// The near-field rung for a quality, or for settings.near_field_model when it is set. Throws
// InputError at /settings/near_field_model for an unknown name (a scene built in code; a loaded
// project has been checked).
nearfield::Model near_model_for(const Settings& settings);

Plan make_plan(const Scene& scene);

}  // namespace luxgrid::calc
