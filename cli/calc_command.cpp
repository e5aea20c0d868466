// `luxgrid calc PROJECT [-o DIR] [--quality Q] [--scene normal|emergency|daylight] [--no-report]
//  [--part-plots] [--scale MIN:MAX] [--check] [--with-cost] [--arrays npy]`
#include <cstdio>

#include "app/run_project.h"
#include "cli/commands.h"
#include "report/en17037_checks.h"
#include "util/error.h"
#include "util/output_names.h"

namespace luxgrid::cli {

int run_calc(const CalcArgs& args) {
  app::RunOptions options;
  if (!args.quality.empty()) options.quality = calc::quality_from_string(args.quality);
  if (!args.scale.empty()) options.scale = report::parse_scale(args.scale);
  if (!args.scene.empty()) {
    options.scene = args.scene == "emergency"  ? calc::LightingScene::emergency
                    : args.scene == "daylight" ? calc::LightingScene::daylight
                                               : calc::LightingScene::normal;
  }
  options.report = !args.no_report;
  options.with_cost = args.with_cost;
  options.arrays_npy = args.arrays == "npy";
  options.part_plots = args.part_plots;
  options.show_progress = true;
  const std::filesystem::path out =
      args.out.empty() ? app::default_output_dir(args.project) : std::filesystem::path(args.out);
  auto warn = [](const std::string& w) {
    std::fprintf(stderr, "luxgrid: warning: %s\n", w.c_str());
  };
  options.on_load_warning = warn;
  const auto outcome = app::run_project(args.project, out, options);
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
  if (outcome.en17037) std::printf("%s", report::format_en17037(*outcome.en17037).c_str());
  if (outcome.cost)
    std::printf("cost of accuracy:\n%s", report::format_cost_table(*outcome.cost).c_str());
  std::printf("results written to %s\n", out.string().c_str());
  for (const auto& k : outcome.kept)
    std::printf("%s kept from the previous run (this run did not write it: %s)\n", k.c_str(),
                k == kReportFile ? "--no-report" : "no --part-plots");
  if (args.check && !report::all_met(outcome.checks)) {
    std::fprintf(stderr, "luxgrid: requirements not met (--check)\n");
    return 3;
  }
  return 0;
}

}  // namespace luxgrid::cli
