#include "cli/command_line.h"

#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "cli/threads.h"

namespace luxgrid::cli {

namespace {

// Each subcommand's arguments live in a shared object the parser fills; choosing the subcommand
// binds them to its run function.
template <class Args>
std::shared_ptr<Args> bind(CLI::App* cmd, std::function<int()>& run, int (*runner)(const Args&)) {
  auto args = std::make_shared<Args>();
  cmd->callback([args, runner, &run] { run = [args, runner] { return runner(*args); }; });
  return args;
}

void add_calc(CLI::App& app, std::function<int()>& run) {
  CLI::App* cmd = app.add_subcommand(
      "calc", "Calculate a project: results.json, CSV and PNG per surface, report.html");
  auto opt = bind(cmd, run, &run_calc);
  cmd->add_option("PROJECT", opt->project, "Project file (JSON)")->required();
  cmd->add_option("-o,--output", opt->out,
                  "Output folder (default: <project>.out beside the project)");
  cmd->add_option("--quality", opt->quality, "Override settings.quality")
      ->check(CLI::IsMember({"draft", "standard", "high", "reference"}));
  cmd->add_option("--scene", opt->scene,
                  "Override settings.scene: normal, emergency (EN 1838: direct light from the "
                  "luminaires' emergency output, escape-route and open-area checks), or daylight "
                  "(the sky through the openings: docs/daylight.md)")
      ->check(CLI::IsMember({"normal", "emergency", "daylight"}));
  cmd->add_flag("--no-report", opt->no_report, "Do not write report.html");
  cmd->add_flag("--part-plots", opt->part_plots,
                "Also plot each grid's direct and reflected light: <surface>_direct.png and "
                "<surface>_indirect.png (when reflected light was calculated)");
  cmd->add_option("--scale", opt->scale,
                  "Fix the colour scale of every plot to MIN:MAX lux (e.g. 0:1000)");
  cmd->add_option(
         "--arrays", opt->arrays,
         "Also write each surface's points and results as a NumPy array: npy (<surface>.npy)")
      ->check(CLI::IsMember({"npy"}));
  cmd->add_flag("--check", opt->check,
                "Exit with code 3 when a requirement is not met or cannot be calculated");
  cmd->add_flag("--with-cost", opt->with_cost,
                "Also run draft/standard/high/reference and put the cost table into the report");
}

void add_report(CLI::App& app, std::function<int()>& run) {
  CLI::App* cmd = app.add_subcommand(
      "report",
      "Write the CSVs, plots and report.html of a calculation again from its results.json, "
      "without calculating (e.g. with another colour scale)");
  auto opt = bind(cmd, run, &run_report);
  cmd->add_option("RESULTS", opt->results, "results.json of a calculation")->required();
  cmd->add_option("-o,--output", opt->out,
                  "Output folder (default: the folder results.json lies in)");
  cmd->add_option("--scale", opt->scale,
                  "Fix the colour scale of every plot to MIN:MAX lux (e.g. 0:1000)");
  cmd->add_flag("--part-plots", opt->part_plots,
                "Also plot each grid's direct and reflected light (when reflected light was "
                "calculated)");
}

void add_validate(CLI::App& app, std::function<int()>& run) {
  CLI::App* cmd = app.add_subcommand(
      "validate", "Run the validation cases and compare with their expected values");
  auto opt = bind(cmd, run, &run_validate);
  cmd->add_option(
      "CASES_DIR", opt->cases,
      "Folder of case folders (default: the repository's cases/, found from the binary)");
  cmd->add_option("-o,--output", opt->out, "Output folder for the tables and each case's results")
      ->capture_default_str();
  cmd->add_option("--quality", opt->quality,
                  "Run every case at this quality and hold its checks to the quality's promise "
                  "(standard 1 %, high 0.3 %; docs/validation.md)")
      ->check(CLI::IsMember({"standard", "high"}));
}

void add_info(CLI::App& app, std::function<int()>& run) {
  auto* cmd = app.add_subcommand("info",
                                 "Summarise an IES or EULUMDAT file: flux, LOR, DFF, beam angles, "
                                 "intensities, polar diagram");
  auto opt = bind(cmd, run, &run_info);
  cmd->add_option("file", opt->file, "IES (.ies) or EULUMDAT (.ldt) file")->required();
  cmd->add_flag("--json", opt->json, "print JSON instead of text");
  cmd->add_option("--at", opt->at, "C,gamma in degrees (repeatable): intensity in that direction")
      ->allow_extra_args(false);
  cmd->add_option("-o,--plot", opt->plot,
                  "write a polar diagram PNG (C0-C180 and C90-C270 planes)");
  cmd->add_option("--interpolation", opt->interpolation, "bilinear (default) or bicubic")
      ->check(CLI::IsMember({"bilinear", "bicubic"}));
  cmd->add_flag("--ugr", opt->ugr,
                "add the CIE 190 UGR table (rooms 2H to 12H, five reflectance combinations, "
                "viewed crosswise and endwise)");
}

void add_diff(CLI::App& app, std::function<int()>& run) {
  CLI::App* cmd = app.add_subcommand(
      "diff", "Compare two results.json files (or output folders) point by point");
  auto opt = bind(cmd, run, &run_diff);
  cmd->add_option("A", opt->a, "results.json or output folder to check")->required();
  cmd->add_option("B", opt->b, "results.json or output folder of the reference")->required();
  cmd->add_option(
         "--tol", opt->tol,
         "Largest allowed relative point difference (0.01 = 1 %); above it the exit code is 1")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--promise", opt->promise,
                "Measure as the qualities promise: |A - B| / B at the points brighter than 1 % of "
                "their surface's maximum in B, with the worst point's place and values");
}

void add_cost(CLI::App& app, std::function<int()>& run) {
  CLI::App* cmd =
      app.add_subcommand("cost", "Run a project at every quality and show time against accuracy");
  auto opt = bind(cmd, run, &run_cost);
  cmd->add_option("PROJECT", opt->project, "Project file (JSON)")->required();
}

void add_accuracy(CLI::App& app, std::function<int()>& run) {
  CLI::App* cmd = app.add_subcommand("accuracy",
                                     "Measure NRMS error and time per evaluation of every "
                                     "near-field model (protocol of Luksch2020, docs/accuracy.md)");
  auto opt = bind(cmd, run, &run_accuracy);
  cmd->add_option("-o,--out", opt->out, "Output folder for accuracy.md and accuracy.png")
      ->capture_default_str();
  cmd->add_option("--photometry", opt->photometry,
                  "Folder holding the study's seven Zumtobel LDT files (the full study also reads "
                  "three contrast "
                  "files from ../ies and ../ldt beside it; default: the repository's "
                  "tests/data/photometry/ldt, "
                  "found from the binary)");
  cmd->add_option("--grid", opt->grid, "Receivers per side of the 5 x 5 region (per orientation)")
      ->check(CLI::Range(2, 200));
  cmd->add_flag("--quick", opt->quick,
                "Reduced study for CI: cosine, batwing and one LDT file, 6 x 6 receivers, 3 Monte "
                "Carlo levels");
}

void add_view(CLI::App& app, std::function<int()>& run) {
  CLI::App* cmd = app.add_subcommand(
      "view",
      "Write the project in 3D without calculating (rooms, obstacles, luminaires with their "
      "photometric solids, calculation surfaces): an HTML page, or glTF when FILE ends in .glb");
  auto opt = bind(cmd, run, &run_view);
  cmd->add_option("PROJECT", opt->project, "Project file (JSON)")->required();
  cmd->add_option("-o,--output", opt->out,
                  "The file to write: .html (the default, <project>.view.html beside the "
                  "project) or .glb");
}

}  // namespace

CommandLine parse_command_line(int argc, char** argv) {
  CommandLine line;
  CLI::App app{"luxgrid: illuminance grids from photometric files and a project description"};
  app.set_version_flag("--version", std::string("luxgrid ") + LUXGRID_VERSION);
  app.require_subcommand(1);
  // A process-wide option, accepted before or after the subcommand (fallthrough).
  app.add_option("--threads", line.threads,
                 "Worker threads (default: LUXGRID_THREADS, else every core)")
      ->check(CLI::Range(1, kMaxThreads));
  app.fallthrough();
  add_calc(app, line.run);
  add_report(app, line.run);
  add_validate(app, line.run);
  add_info(app, line.run);
  add_diff(app, line.run);
  add_cost(app, line.run);
  add_accuracy(app, line.run);
  add_view(app, line.run);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    line.run = nullptr;
    line.exit_code = code == 0 ? 0 : 2;  // --help and --version exit 0; usage errors are bad input
  }
  return line;
}

}  // namespace luxgrid::cli
