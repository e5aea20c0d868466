#pragma once
// Whether a scene needs reflected light, and why: the rule the plan applies (calc/plan.cpp,
// make_plan), so the plan states its decision before anything is computed (docs/indirect.md,
// "Pipeline", its item "Decision").
#include <map>
#include <string>

#include "calc/scene.h"

namespace luxgrid::calc::indirect {

struct IndirectDecision {
  bool run = false;
  std::string reason;        // "skipped: all reflectances are 0", "on: ...", ...
  double estimate_lx = 0.0;  // integrating-sphere estimate rho Phi / (A (1 - rho)), max over rooms
  double mean_direct_lx = 0.0;  // mean far-field direct illuminance on the calculation surfaces
  // luminous_flux of each distinct distribution of the luminaires inside rooms (for
  // IndirectOptions::luminous_flux_lm).
  std::map<const photometry::IntensityDistribution*, double> luminous_flux_lm;
};

// Auto mode skips indirect light when the integrating-sphere estimate is below this fraction of
// the mean direct illuminance on the calculation surfaces (1 %: the standard quality's target).
inline constexpr double kAutoSkipFraction = 0.01;

IndirectDecision decide_indirect(const Scene& scene);

}  // namespace luxgrid::calc::indirect
