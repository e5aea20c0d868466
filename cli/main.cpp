// luxgrid: lighting calculations from a project file. This file only wires the subcommands
// together and is the one place that turns errors into messages and exit codes.
#include <cstdio>
#include <exception>
#include <optional>

#include "cli/commands.h"
#include "cli/threads.h"
#include "util/error.h"
#include "util/process_setup.h"

int main(int argc, char** argv) {
  luxgrid::set_up_process();
  CLI::App app{"luxgrid: illuminance grids from photometric files and a project description"};
  app.set_version_flag("--version", std::string("luxgrid ") + LUXGRID_VERSION);
  app.require_subcommand(1);
  // A process-wide option, accepted before or after the subcommand (fallthrough).
  std::optional<int> threads;
  app.add_option("--threads", threads, "Worker threads (default: LUXGRID_THREADS, else every core)")
      ->check(CLI::Range(1, luxgrid::cli::kMaxThreads));
  app.fallthrough();
  luxgrid::cli::Runner run;
  luxgrid::cli::add_calc_command(app, run);
  luxgrid::cli::add_report_command(app, run);
  luxgrid::cli::add_validate_command(app, run);
  luxgrid::cli::add_info_command(app, run);
  luxgrid::cli::add_diff_command(app, run);
  luxgrid::cli::add_cost_command(app, run);
  luxgrid::cli::add_accuracy_command(app, run);
  luxgrid::cli::add_view_command(app, run);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;  // --help and --version exit 0; usage errors are bad input
  }
  try {
    const auto thread_limit = luxgrid::cli::limit_threads(luxgrid::cli::requested_threads(threads));
    return run ? run() : 2;
  } catch (const luxgrid::InputError& e) {
    std::fprintf(stderr, "luxgrid: error: %s\n", e.what());
    return 2;
  } catch (const luxgrid::CalculationError& e) {
    std::fprintf(stderr, "luxgrid: calculation failed: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "luxgrid: internal error: %s\n", e.what());
    return 1;
  }
}
