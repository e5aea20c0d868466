// `luxgrid validate [CASES_DIR] [-o DIR]`
#include <cstdio>
#include <optional>

#include "app/validation.h"
#include "cli/commands.h"
#include "cli/data_paths.h"
#include "report/output_folder.h"

namespace luxgrid::cli {

int run_validate(const ValidateArgs& args) {
  const std::filesystem::path cases =
      args.cases.empty() ? find_repository_path("cases") : std::filesystem::path(args.cases);
  report::OutputFolder folder(args.out, {cases});
  std::optional<calc::Quality> quality;
  if (!args.quality.empty()) quality = calc::quality_from_string(args.quality);
  const app::ValidationReport report = app::run_validation(cases, folder.staging(), quality);
  const std::string md = report.markdown();
  report::write_text_file(folder.file("validation.md"), md);
  report::write_text_file(folder.file("validation.json"), report.json().dump(1) + "\n");
  folder.commit();
  std::fputs(md.c_str(), stdout);
  size_t passed = 0;
  for (const auto& r : report.rows) passed += r.pass;
  std::printf("\n%zu passed, %zu failed\n", passed,
              report.rows.size() - passed + report.case_errors.size());
  std::printf("tables written to %s/validation.md and validation.json\n", args.out.c_str());
  return report.all_passed() ? 0 : 1;
}

}  // namespace luxgrid::cli
