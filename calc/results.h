#pragma once
// What a calculation produced: per-surface illuminance, statistics, the plan that says what was
// simulated and why, and the time each phase took. report/ only reads this.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "calc/glare/observer_result.h"
#include "calc/plan.h"
#include "calc/scene.h"
#include "calc/statistics.h"
#include "geometry/surface_grid.h"

namespace luxgrid::calc {

// All three are maintained values (the initial ones times the maintenance factor), so that
// E = E_direct + E_indirect holds in every output; results.json and the CSV say so.
struct SurfaceResult {
  geometry::SurfaceGrid grid;
  std::vector<double> E_direct;    // lx, maintained
  std::vector<double> E_indirect;  // lx, maintained
  std::vector<double> E;           // lx, maintained: E_direct + E_indirect
  Statistics stats;                // of E, over the active points
  std::optional<double>
      UGR_max;  // observers surfaces: the largest UGR over all observers and views
  // observers surfaces: per observer, each view's UGR, background luminance and terms
  // (calc/glare/ugr.h); E is then the illuminance at the eye facing each view.
  std::vector<glare::ObserverResult> observers;
  // The daylight scene (docs/daylight.md), percent of the unobstructed sky's horizontal
  // illuminance per point: the daylight factor DF = SC + ERC + IRC, the sky component, the
  // externally and the internally reflected components. Empty in the other scenes.
  std::vector<double> DF, SC, ERC, IRC;
  // The daylight scene with direct sun (daylight.sun.direct_normal_lx), lx per point: the sun's
  // light straight through the openings and its reflected part. No part of DF; E_direct and
  // E_indirect (and E) hold them besides the sky's. Empty without direct sun.
  std::vector<double> E_sun_direct, E_sun_reflected;
};

struct Results {
  std::string project;
  Quality quality = Quality::standard;          // the quality the calculation ran at
  double maintenance_factor = 1.0;              // applied to every E above
  LightingScene scene = LightingScene::normal;  // normal lighting, or EN 1838's emergency scene
  Plan plan;
  std::vector<SurfaceResult> surfaces;
  std::vector<std::pair<std::string, double>> timing_s;  // phase -> seconds, in run order
};

}  // namespace luxgrid::calc
