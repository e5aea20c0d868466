#pragma once
// results.json, exactly as docs/project-format.md describes it.
#include <nlohmann/json.hpp>

#include "calc/results.h"

namespace luxgrid::report {

inline constexpr const char* kResultsFormat = "luxgrid-results/1";

nlohmann::json results_to_json(const calc::Results& results);

}  // namespace luxgrid::report
