// `luxgrid report RESULTS.json [-o DIR] [--scale MIN:MAX] [--part-plots]`: the CSVs, plots and
// report.html of a calculation written again from its results.json alone (docs/report.md).
#include <cstdio>

#include "app/report_results.h"
#include "cli/commands.h"

namespace luxgrid::cli {

int run_report(const ReportArgs& args) {
  app::ReportOptions options;
  if (!args.scale.empty()) options.scale = report::parse_scale(args.scale);
  options.part_plots = args.part_plots;
  std::filesystem::path out = args.out;
  if (out.empty()) {
    out = std::filesystem::path(args.results).parent_path();
    if (out.empty()) out = ".";
  }
  const auto outcome = app::report_results(args.results, out, options);
  for (const auto& w : outcome.warnings) std::fprintf(stderr, "luxgrid: warning: %s\n", w.c_str());
  std::printf("report written to %s\n", out.string().c_str());
  return 0;
}

}  // namespace luxgrid::cli
