// `luxgrid cost PROJECT`: what accuracy costs on the user's own project. Runs the project at
// draft, standard, high and reference and prints, per surface, wall time, Eavg, Emin, U0 and the
// largest and mean point difference to the reference run beside the plan's own estimate of it,
// then what each level promises and simulated.
#include <cstdio>

#include "app/run_project.h"
#include "cli/commands.h"
#include "project/project_file.h"

namespace luxgrid::cli {

int run_cost(const CostArgs& args) {
  const project::Project loaded = project::load_project(args.project);
  for (const auto& w : loaded.scene.warnings)
    std::fprintf(stderr, "luxgrid: warning: %s\n", w.text().c_str());
  const auto table = app::run_cost(loaded.scene, true);
  // Each level's surfaces whose estimated error exceeds its promise (the table marks them "!").
  for (const auto& level : table.levels)
    for (const auto& w : level.warnings)
      std::fprintf(stderr, "luxgrid: warning: %s: %s\n", level.quality.c_str(), w.c_str());
  std::fputs(report::format_cost_table(table).c_str(), stdout);
  return 0;
}

}  // namespace luxgrid::cli
