#pragma once
// The command line: every subcommand's options and help texts, parsed with CLI11 (this header
// keeps CLI11 out of every other file: it costs seconds of compile time per file that includes it).
#include <functional>
#include <optional>

namespace luxgrid::cli {

struct CommandLine {
  // The chosen subcommand, bound to its arguments; empty when parsing ended the process
  // (`--help`, `--version` or a usage error: exit_code says how).
  std::function<int()> run;
  int exit_code = 2;
  std::optional<int> threads;  // --threads, before or after the subcommand
};

// Parses argv; prints help, the version or the usage error itself (CLI11's words) when there is
// one.
CommandLine parse_command_line(int argc, char** argv);

}  // namespace luxgrid::cli
