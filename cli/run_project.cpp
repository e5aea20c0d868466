#include "cli/run_project.h"

#include <chrono>

#include "calc/pipeline.h"
#include "calc/plan_estimates.h"
#include "calc/project_file.h"
#include "calc/safe_json.h"
#include "cli/progress.h"
#include "report/colour_rendering.h"
#include "report/output_folder.h"
#include "report/write_outputs.h"
#include "util/error.h"
#include "util/output_names.h"
#include "util/sha256.h"

namespace luxgrid::cli {

std::filesystem::path default_output_dir(const std::filesystem::path& project) {
  std::filesystem::path out = project;
  out.replace_extension(".out");
  return out;
}

LoadedProject load_project_with_requirements(const std::filesystem::path& project) {
  // One safe parse (size, depth, duplicate keys, number range) feeds both readers.
  // The bytes are read once: the hash in results.json is of exactly what was parsed.
  const std::string text = calc::read_bounded_file(project);
  const nlohmann::json doc = calc::parse_json_text(text, project.string());
  const std::string label = project.filename().string();
  LoadedProject out;
  out.scene = calc::parse_project(report::without_requirements(doc), label, project.parent_path());
  out.scene.project_file = project;
  out.scene.project_sha256 = sha256_hex(text);
  out.requirements = report::parse_requirements(doc, label);
  return out;
}

std::vector<std::filesystem::path> input_files(const calc::Scene& scene) {
  std::vector<std::filesystem::path> out{scene.project_file};
  const std::filesystem::path dir = scene.project_file.parent_path();
  for (const auto& [name, p] : scene.photometry) {
    if (p.format != "builtin") out.push_back(dir / p.source);
  }
  return out;
}

RunOutcome run_project(const std::filesystem::path& project, const std::filesystem::path& out_dir,
                       const RunOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  LoadedProject loaded = load_project_with_requirements(project);
  calc::Scene& scene = loaded.scene;
  if (options.quality) scene.settings.quality = *options.quality;
  const double load_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (options.on_load_warning)
    for (const auto& w : scene.warnings) options.on_load_warning(w);

  // Everything that can reject the input has run: only now does an output folder appear.
  report::OutputFolder folder(out_dir, input_files(scene));
  RunOutcome outcome;
  try {
    outcome.results = calc::run_scene(scene, options.show_progress ? make_progress("calculating") : calc::Progress{});
  } catch (const InputError& e) {
    // Found only while calculating (a room whose faces exceed the patch budget): name the file.
    end_progress();
    throw InputError(project.filename().string() + ": " + e.what());
  }
  end_progress();
  outcome.results.timing_s.insert(outcome.results.timing_s.begin(), {"load", load_s});
  const auto ra = report::scene_colour_rendering(scene);
  outcome.checks = report::check_requirements(outcome.results, loaded.requirements, {ra.Ra, ra.source});
  if (options.with_cost) outcome.cost = run_cost(scene, options.show_progress);

  report::OutputOptions out;
  out.report = options.report;
  out.arrays_npy = options.arrays_npy;
  out.scale = options.scale;
  out.scene = &scene;
  out.checks = outcome.checks;
  out.cost = outcome.cost ? &*outcome.cost : nullptr;
  out.version = LUXGRID_VERSION;
  // Scene warnings (legal but suspicious input, naming the object) first, then the outputs'.
  outcome.warnings = scene.warnings;
  outcome.scene_warnings = scene.warnings.size();
  // The plan's (an error estimate above the quality's promise): printed with the outputs'.
  for (const auto& w : outcome.results.plan.warnings) outcome.warnings.push_back(w);
  for (auto& w : report::write_outputs(outcome.results, folder, out)) outcome.warnings.push_back(std::move(w));
  // --no-report does not ask to delete the report of an earlier run into the same folder.
  if (!options.report) folder.keep_from_previous({kReportFile});
  folder.commit();
  outcome.kept = folder.kept();
  return outcome;
}

report::CostTable run_cost(const calc::Scene& base, bool show_progress) {
  report::CostTable table;
  std::vector<calc::Results> runs;
  for (calc::Quality q : {calc::Quality::draft, calc::Quality::standard, calc::Quality::high, calc::Quality::reference}) {
    calc::Scene scene = base;
    scene.settings.quality = q;
    const auto t0 = std::chrono::steady_clock::now();
    runs.push_back(calc::run_scene(
        scene, show_progress ? make_progress(std::string("cost: ") + calc::to_string(q)) : calc::Progress{}));
    end_progress();
    report::CostLevel level;
    level.quality = calc::to_string(q);
    level.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    level.direct = runs.back().plan.direct;
    level.indirect = runs.back().plan.indirect;
    level.visibility = runs.back().plan.visibility;
    level.promise = runs.back().plan.promise;
    level.promised_error = calc::promised_error(q);
    level.warnings = runs.back().plan.warnings;
    table.levels.push_back(std::move(level));
  }
  const calc::Results& ref = runs.back();
  for (size_t k = 0; k < runs.size(); ++k) {
    for (size_t s = 0; s < runs[k].surfaces.size(); ++s) {
      const auto& sr = runs[k].surfaces[s];
      const auto& estimates = runs[k].plan.estimates;
      table.levels[k].surfaces.push_back({sr.grid.name, sr.stats,
                                          report::point_difference(sr.E, ref.surfaces[s].E),
                                          s < estimates.size() ? estimates[s].total() : 0.0});
    }
  }
  return table;
}

}  // namespace luxgrid::cli
