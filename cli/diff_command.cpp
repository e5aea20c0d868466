// `luxgrid diff A B [--tol T]`: per surface, the largest and mean relative point difference of A
// against B (the reference) and the statistics side by side. Exit 0 when every difference is
// within --tol (a fraction, default 0: report only, never fail), 1 above it, 2 on bad input.
#include <cstdio>

#include "cli/commands.h"
#include "report/diff.h"
#include "util/error.h"

namespace luxgrid::cli {

int run_diff(const DiffArgs& args) {
  const auto a = report::read_results_file(args.a);
  const auto b = report::read_results_file(args.b);
  const auto d = report::diff_results(a, args.a, b, args.b);
  std::fputs(report::format_diff(d).c_str(), stdout);
  if (args.tol >= 0.0 && d.max_rel > args.tol) {
    std::printf("FAIL: above the tolerance of %.3f %%\n", 100.0 * args.tol);
    return 1;
  }
  return 0;
}

}  // namespace luxgrid::cli
