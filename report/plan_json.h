#pragma once
// results.json's `plan` object (docs/project-format.md, "The plan"): every decision of
// calc/plan.h as a value, and a short `summary` in words (report/plan_text.h). Read back by
// `luxgrid report`, which words the plan again from these values.
#include <nlohmann/json.hpp>

#include "calc/plan.h"

namespace luxgrid::report {

nlohmann::json plan_to_json(const calc::Plan& plan);

// The plan written by plan_to_json (its occlusion test and the flux per distribution are not
// kept: the words need neither). Throws nlohmann::json::exception on a missing key or a value
// of the wrong type.
calc::Plan plan_from_json(const nlohmann::json& json);

}  // namespace luxgrid::report
