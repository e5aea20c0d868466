// `luxgrid accuracy [-o|--out DIR] [--quick] [--grid N] [--photometry DIR]`: the
// accuracy-versus-time study of the near-field models (docs/accuracy.md; study/accuracy_study.h
// describes the protocol). Writes DIR/accuracy.md (tables) and DIR/accuracy.png (error versus time
// with the Pareto front).
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "cli/commands.h"
#include "cli/data_paths.h"
#include "study/accuracy_study.h"
#include "util/error.h"

namespace luxgrid::cli {

using namespace luxgrid::study;

int run_accuracy(const AccuracyArgs& args) {
  namespace fs = std::filesystem;
  const fs::path photometry = args.photometry.empty()
                                  ? find_repository_path("tests/data/photometry/ldt")
                                  : fs::path(args.photometry);
  auto files = paper_ldt_files(photometry);
  if (!args.quick)
    for (const auto& f : contrast_files(photometry)) files.push_back(f);
  for (const auto& f : files)
    if (!fs::exists(f))
      throw InputError(SourceLocation{f.string()},
                       "photometry file of the study not found (--photometry)");
  AccuracyOptions options;
  if (args.quick) {
    files.resize(1);
    options.grid = 6;
    options.reference_tolerance = 1e-6;
  }
  if (args.grid > 0) options.grid = args.grid;
  const auto models = accuracy_models(args.quick);
  const auto sets = accuracy_data_sets(files);
  const AccuracyStudy study = run_accuracy_study(
      sets, models, options,
      [](const std::string& what) { std::fprintf(stderr, "accuracy: %s\n", what.c_str()); });
  fs::create_directories(args.out);
  const std::string command = std::string("luxgrid accuracy") + (args.quick ? " --quick" : "") +
                              (args.grid > 0 ? " --grid " + std::to_string(args.grid) : "");
  const std::string md = format_accuracy_markdown(study, command);
  const fs::path md_path = fs::path(args.out) / "accuracy.md";
  {
    std::ofstream f(md_path.string() + ".tmp");
    f << md;
    if (!f) throw CalculationError(md_path.string() + ": cannot write");
  }
  fs::rename(md_path.string() + ".tmp", md_path);
  write_accuracy_plot(study, fs::path(args.out) / "accuracy.png");
  std::fputs(md.c_str(), stdout);
  return 0;
}

}  // namespace luxgrid::cli
