// `luxgrid diff A B [--tol T]`: per surface, the largest and mean relative point difference of A
// against B (the reference) and the statistics side by side. Exit 0 when every difference is
// within --tol (a fraction, default 0: report only, never fail), 1 above it, 2 on bad input.
#include <cstdio>
#include <memory>

#include "cli/commands.h"
#include "report/diff.h"
#include "util/error.h"

namespace luxgrid::cli {

void add_diff_command(CLI::App& app, Runner& run) {
  struct Options {
    std::string a, b;
    double tol = -1.0;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "diff", "Compare two results.json files (or output folders) point by point");
  cmd->add_option("A", opt->a, "results.json or output folder to check")->required();
  cmd->add_option("B", opt->b, "results.json or output folder of the reference")->required();
  cmd->add_option(
         "--tol", opt->tol,
         "Largest allowed relative point difference (0.01 = 1 %); above it the exit code is 1")
      ->check(CLI::NonNegativeNumber);
  cmd->callback([opt, &run] {
    run = [opt] {
      const auto a = report::read_results_file(opt->a);
      const auto b = report::read_results_file(opt->b);
      const auto d = report::diff_results(a, opt->a, b, opt->b);
      std::fputs(report::format_diff(d).c_str(), stdout);
      if (opt->tol >= 0.0 && d.max_rel > opt->tol) {
        std::printf("FAIL: above the tolerance of %.3f %%\n", 100.0 * opt->tol);
        return 1;
      }
      return 0;
    };
  });
}

}  // namespace luxgrid::cli
