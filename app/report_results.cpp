#include "app/report_results.h"

#include "project/safe_json.h"
#include "report/output_folder.h"
#include "report/write_outputs.h"
#include "util/error.h"
#include "util/output_names.h"

namespace luxgrid::app {

namespace {
bool same_folder(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code ec;
  return std::filesystem::exists(b, ec) && std::filesystem::equivalent(a, b, ec);
}
}  // namespace

ReportOutcome report_results(const std::filesystem::path& results_json,
                             const std::filesystem::path& out_dir, const ReportOptions& options) {
  const std::string text =
      project::read_bounded_file(results_json, project::kMaxResultsFileBytes, "results file");
  ReportOutcome outcome;
  outcome.document = report::read_results_document(text, results_json.string());
  report::ResultsDocument& doc = outcome.document;
  // Into its own folder: results.json is written back unchanged, so it is no input the new
  // folder could lose. Anywhere else it is an input like a project file.
  std::filesystem::path folder_of = results_json.parent_path();
  if (folder_of.empty()) folder_of = ".";
  std::vector<std::filesystem::path> inputs;
  if (!same_folder(folder_of, out_dir)) inputs.push_back(results_json);
  report::OutputFolder folder(out_dir, inputs);
  report::OutputOptions out;
  out.report = true;
  out.part_plots = options.part_plots;
  out.scale = options.scale;
  out.scene = &doc.scene;
  out.checks = doc.checks;
  out.en17037 = doc.en17037 ? &*doc.en17037 : nullptr;
  out.types = &doc.types;
  out.results_json = &text;
  out.version = doc.version;
  outcome.warnings = report::write_outputs(doc.results, folder, out);
  // What a calculation wrote and this run does not write again stays: the arrays (--arrays npy)
  // and, without --part-plots, the part plots.
  std::vector<std::string> keep;
  for (const auto& s : doc.results.surfaces) {
    const SurfaceOutputFiles names = surface_output_files(s.grid.name);
    keep.push_back(names.npy);
    if (!options.part_plots) {
      keep.push_back(names.direct_png);
      keep.push_back(names.indirect_png);
    }
  }
  folder.keep_from_previous(std::move(keep));
  folder.commit();
  return outcome;
}

}  // namespace luxgrid::app
