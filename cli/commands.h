#pragma once
// Each subcommand lives in its own file as its arguments and the function that runs it; the
// command line itself (options, help texts, parsing with CLI11) is cli/command_line.cpp, the one
// file that includes CLI11. Each run_* returns the process exit code (0 ok, 1 calculation error,
// 2 bad input or usage, 3 a requirement not met with --check).
#include <string>
#include <vector>

namespace luxgrid::cli {

// `luxgrid calc`: cli/calc_command.cpp.
struct CalcArgs {
  std::string project, out, quality, scale, arrays, scene;
  bool no_report = false, check = false, with_cost = false, part_plots = false;
};
int run_calc(const CalcArgs& args);

// `luxgrid report`: cli/report_command.cpp.
struct ReportArgs {
  std::string results, out, scale;
  bool part_plots = false;
};
int run_report(const ReportArgs& args);

// `luxgrid validate`: cli/validate_command.cpp.
struct ValidateArgs {
  std::string cases, out = "validation.out";
  std::string quality;  // --quality: every case at it, held to its promise (docs/validation.md)
};
int run_validate(const ValidateArgs& args);

// `luxgrid info`: cli/info_command.cpp.
struct InfoArgs {
  std::string file;
  bool json = false;
  std::vector<std::string> at;  // "C,gamma" in degrees, each
  std::string plot;
  std::string interpolation = "bilinear";
  bool ugr = false;
};
int run_info(const InfoArgs& args);

// `luxgrid diff`: cli/diff_command.cpp.
struct DiffArgs {
  std::string a, b;
  double tol = -1.0;     // negative: report only, never fail
  bool promise = false;  // the promise's measure (report::promise_error) instead of the floor's
};
int run_diff(const DiffArgs& args);

// `luxgrid cost`: cli/cost_command.cpp.
struct CostArgs {
  std::string project;
};
int run_cost(const CostArgs& args);

// `luxgrid accuracy`: cli/accuracy_command.cpp.
struct AccuracyArgs {
  std::string out = "accuracy";
  std::string photometry;  // empty: the repository's tests/data/photometry/ldt (cli/data_paths.h)
  bool quick = false;
  int grid = 0;  // 0: the study's default (AccuracyOptions::grid), 6 with --quick
};
int run_accuracy(const AccuracyArgs& args);

// `luxgrid view`: cli/view_command.cpp.
struct ViewArgs {
  std::string project, out;
};
int run_view(const ViewArgs& args);

}  // namespace luxgrid::cli
