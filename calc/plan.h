#pragma once
// The plan: which effects this scene needs, which model computes each, and why. Every decision is
// recorded in words, so results say what was simulated ("indirect: skipped, all reflectances are
// 0"). Later capabilities add their decisions here.
#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "calc/indirect/decision.h"
#include "calc/near_model_name.h"
#include "calc/nearfield/illuminance.h"
#include "calc/scene.h"
#include "calc/visibility.h"

namespace luxgrid::calc {

// The plan's estimate of its own error at one surface (calc/plan_estimates.h): each remaining
// approximation's share, relative to max(E, 1 % of the surface's maximum) at each point as
// `luxgrid cost` measures, the largest over the surface's points. The indirect shares are negative
// when reflected light was not computed (nothing to estimate).
struct SurfaceEstimate {
  std::string surface;
  double direct = 0.0;       // far field and fixed rule where pairs use them: the map's measurement
  double patch_size = -1.0;  // interreflection mesh: |E_ind(h) - E_ind(2h)| / E on probe points
  double bounces = -1.0;     // bounces not followed: the radiosity residual x E_ind / E
  size_t probe_points = 0;   // points the patch-size estimate was measured at
  double total() const {
    return std::max(direct, 0.0) + std::max(patch_size, 0.0) + std::max(bounces, 0.0);
  }
};

struct Plan {
  // Direct light: the near-field rung for area emitters and how the near/far switch is made.
  nearfield::Model near_model = nearfield::Model::standard();
  nearfield::NearFieldSwitch near_switch = nearfield::NearFieldSwitch::automatic;
  // Occlusion test, or null when nothing in the scene can block light (calc/visibility.h).
  std::shared_ptr<const geometry::Visibility> visibility_test;
  std::string direct;  // e.g. "hybrid by an error bound ...: 1200 pairs near-field, ..."
  // Per distinct emitter, the near-field distances the error bound chose and why
  // (calc/far_field_bounds.h); filled by the pipeline, quoted in `direct`.
  std::vector<std::string> near_far_per_emitter;
  // Per distinct distribution, what far-field pairs and the first bounce look intensities up in
  // and why (calc/intensity_lookup.h: the texture and its measured bound, or the table); filled
  // by the pipeline, quoted in `direct`.
  std::vector<std::string> intensity_lookup_per_distribution;
  // Reflected light: whether it runs and why (calc/indirect/decision.h); `indirect` starts as
  // the decision's reason and becomes the run's summary when it ran.
  indirect::IndirectDecision indirect_decision;
  std::string indirect;    // e.g. "skipped: all reflectances are 0"
  std::string visibility;  // e.g. "off: ..."
  std::vector<std::string> notes;
  // What the quality promises and the plan's own error estimate per surface
  // (calc/plan_estimates.h), filled by the pipeline once the illuminance is known.
  std::string promise;                     // e.g. "within 1 % of reference at every point ..."
  std::vector<SurfaceEstimate> estimates;  // one per surface, in the surfaces' order
  // A surface whose estimate exceeds the promise, in words: the CLI prints these on stderr and
  // results.json lists them with its other warnings.
  std::vector<std::string> warnings;
};

// The near-field rung for a quality, or for settings.near_field_model when it is set. Throws
// InputError at /settings/near_field_model for an unknown name (a scene built in code; a loaded
// project has been checked).
nearfield::Model near_model_for(const Settings& settings);

Plan make_plan(const Scene& scene);

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

// The plan's sentence about direct light, once the counts are known.
std::string describe_direct(const Plan& plan, const DirectCounts& counts);

}  // namespace luxgrid::calc
