#include "app/run_project.h"

#include <chrono>

#include <tbb/task_group.h>

#include "app/progress.h"
#include "calc/emergency_scene.h"
#include "calc/pipeline.h"
#include "calc/plan_estimates.h"
#include "project/project_file.h"
#include "report/colour_rendering.h"
#include "report/en17037_checks.h"
#include "report/output_folder.h"
#include "report/plan_text.h"
#include "report/requirement_checks_en1838.h"
#include "report/write_outputs.h"
#include "util/error.h"
#include "util/output_names.h"
#include "util/sha256.h"

namespace luxgrid::app {

std::filesystem::path default_output_dir(const std::filesystem::path& project) {
  std::filesystem::path out = project;
  out.replace_extension(".out");
  return out;
}

// The emergency scene (settings.scene, or --scene) replaces the loaded scene by its emergency
// counterpart (calc/emergency_scene.h) before anything is planned.
void apply_lighting_scene(project::Project& loaded, std::optional<calc::LightingScene> scene) {
  if (scene) loaded.scene.settings.scene = *scene;
  if (loaded.scene.settings.scene == calc::LightingScene::daylight) {
    const std::string file = loaded.scene.project_file.filename().string();
    if (!loaded.scene.daylight)
      throw InputError(SourceLocation(file),
                       "the daylight scene needs a \"daylight\" object (sky, sun, diffuse "
                       "illuminance): docs/daylight.md");
    return;
  }
  if (loaded.scene.settings.scene == calc::LightingScene::emergency) {
    try {
      loaded.scene = calc::make_emergency_scene(loaded.scene);
    } catch (const InputError& e) {
      throw e.in_file(loaded.scene.project_file.filename().string());
    }
  }
  // A daylight project without luminaires run in the normal scene: every illuminance is 0 lx,
  // said rather than printed as a result.
  if (loaded.scene.settings.scene == calc::LightingScene::normal && loaded.scene.luminaires.empty())
    loaded.scene.warnings.push_back(
        {SourceLocation(loaded.scene.project_file.filename().string(), 0, 0, "/luminaires"),
         "the normal scene has no luminaires: every illuminance is 0 lx" +
             std::string(loaded.scene.daylight ? " (daylight is calculated in the daylight scene: "
                                                 "settings.scene \"daylight\" or --scene daylight)"
                                               : "")});
  // An EN 17037 request is answered in the daylight scene only: said, not silently dropped.
  if (loaded.scene.daylight && loaded.scene.daylight->en17037)
    loaded.scene.warnings.push_back(
        {SourceLocation(loaded.scene.project_file.filename().string(), 0, 0, "/daylight/en17037"),
         "EN 17037 is assessed in the daylight scene only (settings.scene \"daylight\" or "
         "--scene daylight); this run's scene is \"" +
             std::string(calc::to_string(loaded.scene.settings.scene)) + "\": no EN 17037 table"});
}

std::vector<report::RequirementCheck> scene_checks(
    const project::Project& loaded, const calc::Results& results,
    const std::optional<daylight::En17037Assessment>& en17037) {
  if (results.scene == calc::LightingScene::emergency) {
    return report::check_en1838(results, loaded.scene.emergency_surfaces);
  }
  const auto ra = report::scene_colour_rendering(loaded.scene);
  auto checks = report::check_requirements(results, loaded.requirements, {ra.Ra, ra.source});
  if (en17037) {
    for (auto& c : report::en17037_checks(*en17037)) checks.push_back(std::move(c));
  }
  return checks;
}

std::vector<std::filesystem::path> input_files(const calc::Scene& scene) {
  std::vector<std::filesystem::path> out{scene.project_file};
  const std::filesystem::path dir = scene.project_file.parent_path();
  for (const auto& [name, p] : scene.photometry) {
    if (p.format != "builtin") out.push_back(dir / p.source);
  }
  return out;
}

void start_worker_threads() {
  tbb::task_group start_workers;
  start_workers.run([] {});
  start_workers.wait();
}

void prepare_project(project::Project& loaded, const RunOptions& options) {
  apply_lighting_scene(loaded, options.scene);
  calc::Scene& scene = loaded.scene;
  if (options.daylight_sky) {
    auto sky = daylight::sky_from_name(*options.daylight_sky);
    if (!sky || !scene.daylight ||
        (sky->kind == daylight::SkyKind::cie_general &&
         !(scene.daylight->sun && scene.daylight->sun->altitude_deg > 0)))
      throw InputError(SourceLocation(scene.project_file.filename().string()),
                       "cannot calculate under the sky \"" + *options.daylight_sky +
                           "\": unknown, or the project has no daylight sun above the horizon");
    if (sky->kind == daylight::SkyKind::cie_general)
      sky->sun =
          daylight::sun_direction(*scene.daylight->sun, scene.daylight->site.north_angle_deg);
    scene.daylight->sky = *sky;
  }
  if (options.quality) loaded.scene.settings.quality = *options.quality;
}

RunOutcome calculate_project(const project::Project& loaded, const RunOptions& options,
                             double load_s) {
  const calc::Scene& scene = loaded.scene;
  RunOutcome outcome;
  try {
    outcome.results = calc::run_scene(
        scene, options.show_progress ? make_progress("calculating") : calc::Progress{});
  } catch (const InputError& e) {
    // Found only while calculating (a room whose faces exceed the patch budget): name the file.
    end_progress();
    throw e.in_file(scene.project_file.filename().string());
  }
  end_progress();
  outcome.results.timing_s.insert(outcome.results.timing_s.begin(), {"load", load_s});
  try {
    outcome.en17037 = report::assess_en17037(outcome.results, scene);
  } catch (const InputError& e) {
    throw e.in_file(scene.project_file.filename().string());
  }
  outcome.checks = scene_checks(loaded, outcome.results, outcome.en17037);
  if (options.with_cost) outcome.cost = run_cost(scene, options.show_progress);
  // Scene warnings (legal but suspicious input, naming the object) first, then the outputs'.
  for (const auto& w : scene.warnings) outcome.warnings.push_back(w.text());
  outcome.scene_warnings = scene.warnings.size();
  // The plan's (an error estimate above the quality's promise): printed with the outputs'.
  for (const auto& w : report::plan_warnings(outcome.results.plan)) outcome.warnings.push_back(w);
  return outcome;
}

void write_run_outputs(RunOutcome& outcome, const project::Project& loaded,
                       report::OutputFolder& folder, const RunOptions& options) {
  report::OutputOptions out;
  out.report = options.report;
  out.arrays_npy = options.arrays_npy;
  out.part_plots = options.part_plots;
  out.scale = options.scale;
  out.scene = &loaded.scene;
  out.checks = outcome.checks;
  out.en17037 = outcome.en17037 ? &*outcome.en17037 : nullptr;
  out.cost = outcome.cost ? &*outcome.cost : nullptr;
  out.version = LUXGRID_VERSION;
  for (auto& w : report::write_outputs(outcome.results, folder, out))
    outcome.warnings.push_back(std::move(w));
  // --no-report does not ask to delete the report of an earlier run into the same folder, nor
  // does leaving out --part-plots ask to delete its part plots.
  std::vector<std::string> keep;
  if (!options.report) keep.push_back(kReportFile);
  if (!options.part_plots) {
    for (const auto& s : outcome.results.surfaces) {
      const SurfaceOutputFiles names = surface_output_files(s.grid.name);
      keep.push_back(names.direct_png);
      keep.push_back(names.indirect_png);
    }
  }
  folder.keep_from_previous(std::move(keep));
  folder.commit();
  outcome.kept = folder.kept();
}

RunOutcome run_project(const std::filesystem::path& project_file,
                       const std::filesystem::path& out_dir, const RunOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  start_worker_threads();
  project::Project loaded = project::load_project(project_file);
  prepare_project(loaded, options);
  const double load_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (options.on_load_warning)
    for (const auto& w : loaded.scene.warnings) options.on_load_warning(w.text());

  // Everything that can reject the input has run: only now does an output folder appear.
  report::OutputFolder folder(out_dir, input_files(loaded.scene));
  RunOutcome outcome = calculate_project(loaded, options, load_s);
  write_run_outputs(outcome, loaded, folder, options);
  return outcome;
}

report::CostTable run_cost(const calc::Scene& base, bool show_progress) {
  report::CostTable table;
  std::vector<calc::Results> runs;
  for (calc::Quality q : {calc::Quality::draft, calc::Quality::standard, calc::Quality::high,
                          calc::Quality::reference}) {
    calc::Scene scene = base;
    scene.settings.quality = q;
    const auto t0 = std::chrono::steady_clock::now();
    runs.push_back(calc::run_scene(
        scene, show_progress ? make_progress(std::string("cost: ") + calc::to_string(q))
                             : calc::Progress{}));
    end_progress();
    report::CostLevel level;
    level.quality = calc::to_string(q);
    level.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    level.direct = report::direct_text(runs.back().plan);
    level.indirect = report::indirect_text(runs.back().plan);
    level.visibility = report::visibility_text(runs.back().plan);
    level.promise = report::promise_text(q);
    level.promised_error = calc::promised_error(q);
    level.warnings = report::plan_warnings(runs.back().plan);
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

}  // namespace luxgrid::app
