// `luxgrid validate [CASES_DIR] [-o DIR]`
#include <cstdio>
#include <memory>

#include "app/validation.h"
#include "cli/commands.h"
#include "cli/data_paths.h"
#include "report/output_folder.h"

namespace luxgrid::cli {

void add_validate_command(CLI::App& app, Runner& run) {
  struct Options {
    std::string cases, out = "validation.out";
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "validate", "Run the validation cases and compare with their expected values");
  cmd->add_option(
      "CASES_DIR", opt->cases,
      "Folder of case folders (default: the repository's cases/, found from the binary)");
  cmd->add_option("-o,--output", opt->out, "Output folder for the tables and each case's results")
      ->capture_default_str();
  cmd->callback([opt, &run] {
    run = [opt] {
      const std::filesystem::path cases =
          opt->cases.empty() ? find_repository_path("cases") : std::filesystem::path(opt->cases);
      report::OutputFolder folder(opt->out, {cases});
      const app::ValidationReport report = app::run_validation(cases, folder.staging());
      const std::string md = report.markdown();
      report::write_text_file(folder.file("validation.md"), md);
      report::write_text_file(folder.file("validation.json"), report.json().dump(1) + "\n");
      folder.commit();
      std::fputs(md.c_str(), stdout);
      size_t passed = 0;
      for (const auto& r : report.rows) passed += r.pass;
      std::printf("\n%zu passed, %zu failed\n", passed,
                  report.rows.size() - passed + report.case_errors.size());
      std::printf("tables written to %s/validation.md and validation.json\n", opt->out.c_str());
      return report.all_passed() ? 0 : 1;
    };
  });
}

}  // namespace luxgrid::cli
