#pragma once
// results.json as `calc` writes it: the outline of the results (report/results_json.h) with what
// a run adds around the values: the maintenance factor and its parts, each surface's requirement
// checks and the overall verdict, and `report_input` (what `luxgrid report` needs). The one
// assembly of the document: report/write_outputs writes it to the output folder, the Python
// module (python/) streams it into a string for `Results.to_json()`.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calc/daylight/en17037.h"
#include "calc/results.h"
#include "calc/scene.h"
#include "report/luminaire_types.h"
#include "report/requirement_checks.h"

namespace luxgrid::report {

// `scene`: null leaves out the maintenance and `report_input` (a results.json read back, where
// they exist already). `output_warnings`: the outputs' own, after the scene's. `en17037`: the
// EN 17037 assessment (report/en17037_checks.h) as `en17037`; null: none.
nlohmann::json results_document(const calc::Results& results, const calc::Scene* scene,
                                const std::vector<RequirementCheck>& checks,
                                const std::vector<LuminaireType>& types,
                                const std::vector<std::string>& output_warnings,
                                const std::string& version,
                                const daylight::En17037Assessment* en17037 = nullptr);

}  // namespace luxgrid::report
