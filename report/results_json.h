#pragma once
// results.json, exactly as docs/project-format.md describes it, and timing.json beside it. The
// times live apart so that two runs of the same input write byte-identical results.json files.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calc/results.h"

namespace luxgrid::report {

inline constexpr const char* kResultsFormat = "luxgrid-results/1";

// `warnings`: legal but suspicious input (calc::Scene::warnings) and output problems, written as
// the top-level "warnings" array (empty when there are none).
nlohmann::json results_to_json(const calc::Results& results,
                               const std::vector<std::string>& warnings = {});

// timing.json: {"timing_s": {phase: seconds, ...}} in run order of the phases.
nlohmann::json timing_to_json(const calc::Results& results);

}  // namespace luxgrid::report
