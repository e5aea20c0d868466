#pragma once
// results.json's `report_input` object (docs/project-format.md): what the outputs need beyond the
// results themselves (rooms, luminaires, surface frames, the luminaire types' data, the
// requirement checks), so that `luxgrid report` writes the CSVs, plots and report.html from a
// results.json alone, byte for byte as `luxgrid calc` wrote them. And the reading back of a
// whole results.json into the data the outputs are written from.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calc/daylight/en17037.h"
#include "calc/results.h"
#include "calc/scene.h"
#include "report/luminaire_types.h"
#include "report/requirement_checks.h"

namespace luxgrid::report {

nlohmann::json report_input_to_json(const calc::Scene& scene, const calc::Results& results,
                                    const std::vector<LuminaireType>& types,
                                    const std::vector<RequirementCheck>& checks);

// Everything read back from a results.json: the results (surfaces, values, statistics, glare,
// the plan), the scene as the outputs use it (no photometric distributions: the types carry what
// the report shows of them), the luminaire types and the checks, and the luxgrid version that
// calculated it.
struct ResultsDocument {
  calc::Results results;
  calc::Scene scene;
  std::vector<LuminaireType> types;
  std::vector<RequirementCheck> checks;
  std::optional<daylight::En17037Assessment> en17037;  // results.json's `en17037`, when there
  std::string version;
};

// Reads `text`, the contents of `file`. Throws InputError naming the file and the JSON pointer
// of what is missing or malformed (or the byte where the JSON itself breaks), and refuses a
// document of another format or one written without `report_input`.
ResultsDocument read_results_document(const std::string& text, const std::string& file);

}  // namespace luxgrid::report
