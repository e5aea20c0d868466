#pragma once
// results.json, exactly as docs/project-format.md describes it.
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

}  // namespace luxgrid::report
