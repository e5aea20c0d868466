#pragma once
// `luxgrid report`: every output of a calculation written again from its results.json alone
// (docs/report.md), through the same writer `luxgrid calc` uses once it has calculated.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "report/colour_scale.h"
#include "report/report_input_json.h"

namespace luxgrid::app {

struct ReportOptions {
  std::optional<report::ColourScale> scale;  // --scale MIN:MAX
  bool part_plots = false;                   // --part-plots
};

struct ReportOutcome {
  report::ResultsDocument document;   // what was read
  std::vector<std::string> warnings;  // the outputs'
};

// Reads `results_json` and writes results.json (the same bytes), the CSVs, plots, report.html
// and timing.json (its own phase) into `out_dir` atomically (report/output_folder.h). `out_dir`
// may be the folder results.json lies in: the file is read before anything is written, and
// written back unchanged. Throws InputError naming the file and the JSON pointer of what is
// missing or malformed.
ReportOutcome report_results(const std::filesystem::path& results_json,
                             const std::filesystem::path& out_dir, const ReportOptions& options);

}  // namespace luxgrid::app
