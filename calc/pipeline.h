#pragma once
// The whole calculation of a loaded scene: plan, direct, indirect, statistics, timings.
#include "calc/direct.h"
#include "calc/results.h"

namespace luxgrid::calc {

// Throws CalculationError naming the surface and the first point (index, position) or
// statistic that is not a finite number: results never hold NaN or infinities.
Results run_scene(const Scene& scene, const Progress& progress = {});

}  // namespace luxgrid::calc
