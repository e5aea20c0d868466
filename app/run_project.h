#pragma once
// Load a project, calculate it and write its output folder: the shared path of `calc`,
// `validate` and `cost`.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "calc/daylight/en17037.h"
#include "calc/results.h"
#include "calc/scene.h"
#include "project/project_file.h"
#include "report/colour_scale.h"
#include "report/diff.h"
#include "report/output_folder.h"
#include "report/requirement_checks.h"

namespace luxgrid::app {

struct RunOptions {
  std::optional<calc::Quality> quality;      // overrides the project's setting
  std::optional<calc::LightingScene> scene;  // --scene: overrides settings.scene
  bool show_progress = false;
  bool report = true;                        // report.html (--no-report switches it off)
  std::optional<report::ColourScale> scale;  // --scale MIN:MAX
  bool with_cost = false;                    // --with-cost: the cost table into the report
  bool arrays_npy = false;                   // --arrays npy: <surface>.npy per surface
  bool part_plots = false;  // --part-plots: <surface>_direct.png, <surface>_indirect.png
  // The daylight scene's sky instead of the project's ("1".."15", "cie-overcast", "uniform"):
  // the validation cases run one project under every sky (cases/cie171_5_9_*).
  std::optional<std::string> daylight_sky;
  // Called with each of the scene's warnings as soon as the project is loaded (before a long
  // calculation, so a project in the wrong units says so at once); RunOutcome::warnings lists
  // them too.
  std::function<void(const std::string&)> on_load_warning;
};

struct RunOutcome {
  calc::Results results;
  std::vector<std::string> warnings;  // the scene's first, then the plan's, then the outputs'
  size_t scene_warnings = 0;          // how many of them are the scene's
  std::vector<report::RequirementCheck> checks;  // empty when the project states none
  std::optional<report::CostTable> cost;         // with_cost only
  // Files of the previous output carried over because this run's flags did not write them
  // (report.html under --no-report, the part plots without --part-plots).
  std::vector<std::string> kept;
  // The daylight scene's EN 17037 assessment, when the project asks (daylight.en17037); its
  // asked level's checks are among `checks`.
  std::optional<daylight::En17037Assessment> en17037;
};

// The emergency scene (settings.scene, or `scene` when given) replaces the loaded scene by its
// emergency counterpart (calc/emergency_scene.h).
void apply_lighting_scene(project::Project& loaded, std::optional<calc::LightingScene> scene);

// The checks of a calculated scene: the project's EN 12464-1 requirements in the normal scene,
// EN 1838's on its escape routes and open areas in the emergency scene; in the daylight scene
// the project's requirements and the checks of `en17037` (report/en17037_checks.h), when given.
std::vector<report::RequirementCheck> scene_checks(
    const project::Project& loaded, const calc::Results& results,
    const std::optional<daylight::En17037Assessment>& en17037 = std::nullopt);

// Loads `project`, runs it and writes every output into `out_dir` atomically: the steps below,
// in this order (the Python module, python/, runs them one by one).
RunOutcome run_project(const std::filesystem::path& project, const std::filesystem::path& out_dir,
                       const RunOptions& options);

// oneTBB's worker threads started while the project loads on this thread, rather than by the
// first parallel loop, which would otherwise run alone on this thread until they are up.
void start_worker_threads();

// The loaded project made ready to calculate: the lighting scene applied (options.scene), the
// quality overridden (options.quality).
void prepare_project(project::Project& loaded, const RunOptions& options);

// Calculates a prepared project: the results (with `load_s` as their "load" phase), the checks,
// the warnings (the scene's, then the plan's) and, with_cost, the cost table. An InputError found
// only while calculating names the project file.
RunOutcome calculate_project(const project::Project& loaded, const RunOptions& options,
                             double load_s);

// Writes every output of a calculated project into `folder` (report/write_outputs), adds the
// outputs' warnings to outcome.warnings, and commits the folder (carrying over what this run's
// options did not write: outcome.kept).
void write_run_outputs(RunOutcome& outcome, const project::Project& loaded,
                       report::OutputFolder& folder, const RunOptions& options);

// The scene at draft, standard, high and reference; differences against the reference run.
report::CostTable run_cost(const calc::Scene& scene, bool show_progress);

// The files a run reads (project, photometric files): the output folder may not replace them.
std::vector<std::filesystem::path> input_files(const calc::Scene& scene);

// `<project without extension>.out`, beside the project file.
std::filesystem::path default_output_dir(const std::filesystem::path& project);

}  // namespace luxgrid::app
