// `luxgrid diff A B [--tol T] [--promise]`: per surface, the largest and mean relative point
// difference of A against B (the reference) and the statistics side by side; with --promise the
// quality promise's measure instead (report::promise_error) and where its worst point is. Exit 0
// when every difference is within --tol (a fraction; without it: report only, never fail), 1
// above it, 2 on bad input.
#include <cstdio>

#include "cli/commands.h"
#include "report/diff.h"
#include "util/error.h"

namespace luxgrid::cli {

int run_diff(const DiffArgs& args) {
  const auto a = report::read_results_file(args.a);
  const auto b = report::read_results_file(args.b);
  const auto d = report::diff_results(a, args.a, b, args.b);
  std::fputs((args.promise ? report::format_promise_diff(d) : report::format_diff(d)).c_str(),
             stdout);
  const double measured = args.promise ? d.promise_max_rel : d.max_rel;
  if (args.tol >= 0.0 && measured > args.tol) {
    std::printf("FAIL: above the tolerance of %.3f %%\n", 100.0 * args.tol);
    return 1;
  }
  return 0;
}

}  // namespace luxgrid::cli
