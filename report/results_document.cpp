#include "report/results_document.h"

#include "report/en17037_checks.h"
#include "report/report_input_json.h"
#include "report/results_json.h"

namespace luxgrid::report {

nlohmann::json results_document(const calc::Results& results, const calc::Scene* scene,
                                const std::vector<RequirementCheck>& checks,
                                const std::vector<LuminaireType>& types,
                                const std::vector<std::string>& output_warnings,
                                const std::string& version,
                                const daylight::En17037Assessment* en17037) {
  // The scene's warnings (legal but suspicious input) and the outputs', as the terminal shows
  // them.
  std::vector<std::string> all_warnings;
  if (scene)
    for (const auto& w : scene->warnings) all_warnings.push_back(w.text());
  all_warnings.insert(all_warnings.end(), output_warnings.begin(), output_warnings.end());
  ResultsOrigin origin;
  origin.version = version;
  if (scene) origin.project_sha256 = scene->project_sha256;
  // Without the point arrays: write_results_json streams them from `results`.
  nlohmann::json j = results_outline_json(results, all_warnings, origin);
  if (scene) {
    // The maintenance factor every E includes, and its parts when the project gave them [CIE97].
    const auto& settings = scene->settings;
    nlohmann::json m = {{"factor", settings.maintenance_factor}};
    if (const auto& p = settings.maintenance_parts) {
      m["LLMF"] = p->LLMF;
      m["LSF"] = p->LSF;
      m["LMF"] = p->LMF;
      m["RSMF"] = p->RSMF;
    }
    j["maintenance"] = std::move(m);
  }
  if (!checks.empty()) {
    // Per surface, each requirement with its verdict and margin; at the top, the overall verdict.
    for (auto& s : j["surfaces"]) {
      for (const auto& c : checks) {
        if (c.surface == s["name"]) s["requirements"].push_back(check_to_json(c));
      }
    }
    j["requirements_met"] = all_met(checks);
  }
  if (en17037) j["en17037"] = en17037_to_json(*en17037);
  // What `luxgrid report` needs to write every other output again from this file.
  if (scene) j["report_input"] = report_input_to_json(*scene, results, types, checks);
  return j;
}

}  // namespace luxgrid::report
