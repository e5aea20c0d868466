// `luxgrid calc PROJECT [-o DIR] [--quality Q] [--scene normal|emergency|daylight] [--no-report]
//  [--part-plots] [--scale MIN:MAX] [--check] [--with-cost] [--arrays npy]`
#include <cstdio>
#include <memory>

#include "app/run_project.h"
#include "cli/commands.h"
#include "util/error.h"
#include "util/output_names.h"

namespace luxgrid::cli {

void add_calc_command(CLI::App& app, Runner& run) {
  struct Options {
    std::string project, out, quality, scale, arrays, scene;
    bool no_report = false, check = false, with_cost = false, part_plots = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "calc", "Calculate a project: results.json, CSV and PNG per surface, report.html");
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
  cmd->callback([opt, &run] {
    run = [opt] {
      app::RunOptions options;
      if (!opt->quality.empty()) options.quality = calc::quality_from_string(opt->quality);
      if (!opt->scale.empty()) options.scale = report::parse_scale(opt->scale);
      if (!opt->scene.empty()) {
        options.scene = opt->scene == "emergency"  ? calc::LightingScene::emergency
                        : opt->scene == "daylight" ? calc::LightingScene::daylight
                                                   : calc::LightingScene::normal;
      }
      options.report = !opt->no_report;
      options.with_cost = opt->with_cost;
      options.arrays_npy = opt->arrays == "npy";
      options.part_plots = opt->part_plots;
      options.show_progress = true;
      const std::filesystem::path out = opt->out.empty() ? app::default_output_dir(opt->project)
                                                         : std::filesystem::path(opt->out);
      auto warn = [](const std::string& w) {
        std::fprintf(stderr, "luxgrid: warning: %s\n", w.c_str());
      };
      options.on_load_warning = warn;
      const auto outcome = app::run_project(opt->project, out, options);
      // The scene's warnings were printed on loading; the outputs' (after them in the list) now.
      for (size_t k = outcome.scene_warnings; k < outcome.warnings.size(); ++k)
        warn(outcome.warnings[k]);
      for (const auto& s : outcome.results.surfaces) {
        std::printf("%-24s Emin %9.2f  Eavg %9.2f  Emax %9.2f lx  U0 %.3f\n", s.grid.name.c_str(),
                    s.stats.Emin, s.stats.Eavg, s.stats.Emax, s.stats.U0);
      }
      if (!outcome.checks.empty()) {
        std::printf("requirements:\n%s", report::format_checks(outcome.checks).c_str());
      }
      if (outcome.cost)
        std::printf("cost of accuracy:\n%s", report::format_cost_table(*outcome.cost).c_str());
      std::printf("results written to %s\n", out.string().c_str());
      for (const auto& k : outcome.kept)
        std::printf("%s kept from the previous run (this run did not write it: %s)\n", k.c_str(),
                    k == kReportFile ? "--no-report" : "no --part-plots");
      if (opt->check && !report::all_met(outcome.checks)) {
        std::fprintf(stderr, "luxgrid: requirements not met (--check)\n");
        return 3;
      }
      return 0;
    };
  });
}

}  // namespace luxgrid::cli
