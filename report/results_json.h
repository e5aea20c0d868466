#pragma once
// results.json, exactly as docs/project-format.md describes it, and timing.json beside it. The
// times live apart so that two runs of the same input write byte-identical results.json files.
#include <ostream>
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
// the top-level "warnings" array (empty when there are none). The whole document, point arrays
// included: for tests and small results; results.json itself is written by write_results_json.
nlohmann::json results_to_json(const calc::Results& results,
                               const std::vector<std::string>& warnings = {},
                               const ResultsOrigin& origin = {});

// The same document without its per-point arrays: each surface's "points", "normals", "active",
// "E", "E_direct" and "E_indirect" hold a placeholder that write_results_json fills from
// `results`. Callers may add keys (the CLI adds "maintenance" and "requirements").
nlohmann::json results_outline_json(const calc::Results& results,
                                    const std::vector<std::string>& warnings = {},
                                    const ResultsOrigin& origin = {});

// Writes `outline` (from results_outline_json) to `out` byte for byte as the whole document's
// dump(1) followed by a newline, the point arrays streamed from `results` rather than built as
// JSON values, their elements formatted in parallel a chunk at a time: a 10^6-point grid's
// results.json costs little memory beyond the results themselves (a few chunks' text, and for a
// surface without reflected light its E array's text, which E_direct repeats).
void write_results_json(std::ostream& out, const nlohmann::json& outline,
                        const calc::Results& results);

// timing.json: {"timing_s": {phase: seconds, ...}} in run order of the phases.
nlohmann::json timing_to_json(const calc::Results& results);

}  // namespace luxgrid::report
