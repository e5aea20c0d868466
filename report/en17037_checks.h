#pragma once
// EN 17037 daylight provision on the daylight scene's results [EN17037]: the assessment of each
// reference plane (calc/daylight/en17037.h) and the checks of the level the project asks for,
// as RequirementChecks, so the terminal, results.json, the report's compliance table and
// `--check` treat them as they treat EN 12464-1's (docs/daylight.md, docs/compliance.md).
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calc/daylight/en17037.h"
#include "calc/results.h"
#include "calc/scene.h"
#include "report/requirement_checks.h"

namespace luxgrid::report {

// The checks' quantities: the share of the plane with DF >= D_T (the target, over 50 % or, top
// lit, 95 %) and with DF >= D_TM (the minimum target, over 95 %), in percent of the plane.
inline constexpr const char* kEn17037TargetQuantity = "DF>=D_T";
inline constexpr const char* kEn17037MinimumTargetQuantity = "DF>=D_TM";

// The project's EN 17037 request assessed on the results: none unless the results are the
// daylight scene's and the project asks (daylight.en17037). Throws InputError when a reference
// plane is missing from the results.
std::optional<daylight::En17037Assessment> assess_en17037(const calc::Results& results,
                                                          const calc::Scene& scene);

// The asked level's two checks per reference plane, in the planes' order.
std::vector<RequirementCheck> en17037_checks(const daylight::En17037Assessment& a);

// results.json's `en17037` object (docs/project-format.md) and its reading back (throws
// nlohmann::json exceptions on a malformed one, as report_input_json's readers).
nlohmann::json en17037_to_json(const daylight::En17037Assessment& a);
daylight::En17037Assessment en17037_from_json(const nlohmann::json& j);

// The terminal's table: per plane its points, average DF and uniformity, and per level each
// target's daylight factor, the share of the plane reaching it and the verdict.
std::string format_en17037(const daylight::En17037Assessment& a);

}  // namespace luxgrid::report
