#pragma once
// The daylight scene (docs/daylight.md): at every point the sky component (the sky seen through
// the openings of the point's rooms, hidden by what lies inside them) and the externally
// reflected component (the ground below the horizon, a uniform plane of luminance
// rho_g E_h / pi [CIE171]), through unglazed or glazed openings; E = DF x E_h / 100 under the
// given sky. The internally reflected component is not built yet (0, and the plan says so).
#include "calc/direct.h"
#include "calc/results.h"

namespace luxgrid::calc {

// The relative tolerance of the adaptive integration over openings at each quality: the
// quality's promise (1 % standard, 0.3 % high), 5 % at draft, 1e-4 at reference.
double daylight_tolerance(Quality q);

// The whole daylight calculation of a scene whose settings.scene is daylight. Throws
// InputError for what it cannot calculate (a cylindrical or observers surface).
Results run_daylight_scene(const Scene& scene, const Progress& progress = {});

}  // namespace luxgrid::calc
