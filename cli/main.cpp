// luxgrid: lighting calculations from a project file. This file only runs the subcommand the
// command line chose (cli/command_line.h) and is the one place that turns errors into messages
// and exit codes.
#include <cstdio>
#include <exception>

#include "cli/command_line.h"
#include "cli/threads.h"
#include "util/error.h"
#include "util/process_setup.h"

int main(int argc, char** argv) {
  luxgrid::set_up_process();
  const luxgrid::cli::CommandLine line = luxgrid::cli::parse_command_line(argc, argv);
  if (!line.run) return line.exit_code;
  try {
    const auto thread_limit =
        luxgrid::cli::limit_threads(luxgrid::cli::requested_threads(line.threads));
    return line.run();
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
