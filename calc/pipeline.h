#pragma once
// The whole calculation of a loaded scene: plan, direct, indirect, statistics, timings.
#include "calc/direct.h"
#include "calc/results.h"

namespace luxgrid::calc {

Results run_scene(const Scene& scene, const Progress& progress = {});

}  // namespace luxgrid::calc
