#pragma once
// Each subcommand lives in its own file and registers itself on the CLI11 app. `run` is set to the
// function main() calls when that subcommand was chosen; it returns the process exit code
// (0 ok, 1 calculation error, 2 bad input or usage, 3 a requirement not met with --check).
#include <functional>

#include <CLI/CLI.hpp>

namespace luxgrid::cli {

using Runner = std::function<int()>;

void add_calc_command(CLI::App& app, Runner& run);      // cli/calc_command.cpp
void add_report_command(CLI::App& app, Runner& run);    // cli/report_command.cpp
void add_validate_command(CLI::App& app, Runner& run);  // cli/validate_command.cpp
void add_info_command(CLI::App& app, Runner& run);      // cli/info_command.cpp
void add_diff_command(CLI::App& app, Runner& run);      // cli/diff_command.cpp
void add_cost_command(CLI::App& app, Runner& run);      // cli/cost_command.cpp
void add_accuracy_command(CLI::App& app, Runner& run);  // cli/accuracy_command.cpp
void add_view_command(CLI::App& app, Runner& run);      // cli/view_command.cpp

}  // namespace luxgrid::cli
