// `luxgrid report RESULTS.json [-o DIR] [--scale MIN:MAX] [--part-plots]`: the CSVs, plots and
// report.html of a calculation written again from its results.json alone (docs/report.md).
#include <cstdio>
#include <memory>

#include "app/report_results.h"
#include "cli/commands.h"

namespace luxgrid::cli {

void add_report_command(CLI::App& app, Runner& run) {
  struct Options {
    std::string results, out, scale;
    bool part_plots = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "report",
      "Write the CSVs, plots and report.html of a calculation again from its results.json, "
      "without calculating (e.g. with another colour scale)");
  cmd->add_option("RESULTS", opt->results, "results.json of a calculation")->required();
  cmd->add_option("-o,--output", opt->out,
                  "Output folder (default: the folder results.json lies in)");
  cmd->add_option("--scale", opt->scale,
                  "Fix the colour scale of every plot to MIN:MAX lux (e.g. 0:1000)");
  cmd->add_flag("--part-plots", opt->part_plots,
                "Also plot each grid's direct and reflected light (when reflected light was "
                "calculated)");
  cmd->callback([opt, &run] {
    run = [opt] {
      app::ReportOptions options;
      if (!opt->scale.empty()) options.scale = report::parse_scale(opt->scale);
      options.part_plots = opt->part_plots;
      std::filesystem::path out = opt->out;
      if (out.empty()) {
        out = std::filesystem::path(opt->results).parent_path();
        if (out.empty()) out = ".";
      }
      const auto outcome = app::report_results(opt->results, out, options);
      for (const auto& w : outcome.warnings)
        std::fprintf(stderr, "luxgrid: warning: %s\n", w.c_str());
      std::printf("report written to %s\n", out.string().c_str());
      return 0;
    };
  });
}

}  // namespace luxgrid::cli
