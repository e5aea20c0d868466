#pragma once
// results.json, exactly as docs/project-format.md describes it, and timing.json beside it. The
// times live apart so that two runs of the same input write byte-identical results.json files.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calc/results.h"

namespace luxgrid::report {

// Version 2: E_direct and E_indirect became maintained values like E (version 1 wrote them
// initial); E itself means the same in both, so `luxgrid diff` reads either.
inline constexpr const char* kResultsFormat = "luxgrid-results/2";
inline constexpr const char* kResultsFormatV1 = "luxgrid-results/1";

// Where the results came from, for the top of results.json.
struct ResultsOrigin {
  std::string version;         // luxgrid's version
  std::string project_sha256;  // of the project file's bytes; empty: not from a file
};

// `warnings`: legal but suspicious input (calc::Scene::warnings) and output problems, written as
// the top-level "warnings" array (empty when there are none).
nlohmann::json results_to_json(const calc::Results& results,
                               const std::vector<std::string>& warnings = {},
                               const ResultsOrigin& origin = {});

// timing.json: {"timing_s": {phase: seconds, ...}} in run order of the phases.
nlohmann::json timing_to_json(const calc::Results& results);

}  // namespace luxgrid::report
