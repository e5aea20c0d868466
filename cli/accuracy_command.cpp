// `luxgrid accuracy [-o|--out DIR] [--quick] [--grid N] [--photometry DIR]`: the
// accuracy-versus-time study of the near-field models (docs/accuracy.md; study/accuracy_study.h
// describes the protocol). Writes DIR/accuracy.md (tables) and DIR/accuracy.png (error versus time
// with the Pareto front).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "cli/commands.h"
#include "cli/data_paths.h"
#include "study/accuracy_study.h"
#include "util/error.h"

namespace luxgrid::cli {

using namespace luxgrid::study;

void add_accuracy_command(CLI::App& app, Runner& run) {
  struct Options {
    std::string out = "accuracy";
    std::string photometry;  // empty: the repository's tests/data/photometry/ldt (cli/data_paths.h)
    bool quick = false;
    int grid = 0;  // 0: the study's default (AccuracyOptions::grid), 6 with --quick
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("accuracy",
                                     "Measure NRMS error and time per evaluation of every "
                                     "near-field model (protocol of Luksch2020, docs/accuracy.md)");
  cmd->add_option("-o,--out", opt->out, "Output folder for accuracy.md and accuracy.png")
      ->capture_default_str();
  cmd->add_option("--photometry", opt->photometry,
                  "Folder holding the study's seven Zumtobel LDT files (the full study also reads "
                  "three contrast "
                  "files from ../ies and ../ldt beside it; default: the repository's "
                  "tests/data/photometry/ldt, "
                  "found from the binary)");
  cmd->add_option("--grid", opt->grid, "Receivers per side of the 5 x 5 region (per orientation)")
      ->check(CLI::Range(2, 200));
  cmd->add_flag("--quick", opt->quick,
                "Reduced study for CI: cosine, batwing and one LDT file, 6 x 6 receivers, 3 Monte "
                "Carlo levels");
  cmd->callback([opt, &run] {
    run = [opt] {
      namespace fs = std::filesystem;
      const fs::path photometry = opt->photometry.empty()
                                      ? find_repository_path("tests/data/photometry/ldt")
                                      : fs::path(opt->photometry);
      auto files = paper_ldt_files(photometry);
      if (!opt->quick)
        for (const auto& f : contrast_files(photometry)) files.push_back(f);
      for (const auto& f : files)
        if (!fs::exists(f))
          throw InputError(SourceLocation{f.string()},
                           "photometry file of the study not found (--photometry)");
      AccuracyOptions options;
      if (opt->quick) {
        files.resize(1);
        options.grid = 6;
        options.reference_tolerance = 1e-6;
      }
      if (opt->grid > 0) options.grid = opt->grid;
      const auto models = accuracy_models(opt->quick);
      const auto sets = accuracy_data_sets(files);
      const AccuracyStudy study = run_accuracy_study(
          sets, models, options,
          [](const std::string& what) { std::fprintf(stderr, "accuracy: %s\n", what.c_str()); });
      fs::create_directories(opt->out);
      const std::string command = std::string("luxgrid accuracy") + (opt->quick ? " --quick" : "") +
                                  (opt->grid > 0 ? " --grid " + std::to_string(opt->grid) : "");
      const std::string md = format_accuracy_markdown(study, command);
      const fs::path md_path = fs::path(opt->out) / "accuracy.md";
      {
        std::ofstream f(md_path.string() + ".tmp");
        f << md;
        if (!f) throw CalculationError(md_path.string() + ": cannot write");
      }
      fs::rename(md_path.string() + ".tmp", md_path);
      write_accuracy_plot(study, fs::path(opt->out) / "accuracy.png");
      std::fputs(md.c_str(), stdout);
      return 0;
    };
  });
}

}  // namespace luxgrid::cli
