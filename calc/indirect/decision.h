#pragma once
// Whether a scene needs reflected light, and why: the rule the plan applies (calc/plan.cpp,
// make_plan), so the plan states its decision before anything is computed (docs/indirect.md,
// "Pipeline", its item "Decision").
#include <map>
#include <string>

#include "calc/scene.h"

namespace luxgrid::calc::indirect {

// Why reflected light runs or not (report/plan_text.h words it with the numbers below).
enum class IndirectReason {
  off_in_settings,  // skipped: "indirect": "off"
  no_reflectance,   // skipped: every reflectance is 0
  no_luminaires,    // skipped
  forced_on,        // "indirect": "on"
  observers,        // on: an observers surface needs it for UGR's background luminance
  below_threshold,  // skipped: the estimate is below kAutoSkipFraction of the mean direct light
  estimate,         // on: the estimate is not small against the direct light
};

struct IndirectDecision {
  bool run = false;
  IndirectReason reason = IndirectReason::off_in_settings;
  std::string observers_surface;  // observers: its name
  bool sampled = false;           // mean_direct_lx was measured (on at least one point)
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
