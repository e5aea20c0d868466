#pragma once
// What a calculation produced: per-surface illuminance, statistics, the plan that says what was
// simulated and why, and the time each phase took. report/ only reads this.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "calc/glare/observer_result.h"
#include "calc/plan.h"
#include "calc/statistics.h"
#include "geometry/surface_grid.h"

namespace luxgrid::calc {

struct SurfaceResult {
  geometry::SurfaceGrid grid;
  std::vector<double> E_direct;    // lx, initial (before the maintenance factor)
  std::vector<double> E_indirect;  // lx, initial
  std::vector<double> E;           // lx, maintained: (E_direct + E_indirect) * maintenance factor
  Statistics stats;                // of E
  std::optional<double> UGR_max;  // observers surfaces: the largest UGR over all observers and views
  // observers surfaces: per observer, each view's UGR, background luminance and terms
  // (calc/glare/ugr.h); E is then the illuminance at the eye facing each view.
  std::vector<glare::ObserverResult> observers;
};

struct Results {
  std::string project;
  Plan plan;
  std::vector<SurfaceResult> surfaces;
  std::vector<std::pair<std::string, double>> timing_s;  // phase -> seconds, in run order
};

}  // namespace luxgrid::calc
