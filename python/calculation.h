#pragma once
// One calculation as the Python module holds it: the project as calculated and what
// app::calculate_project returned, shared by the Results object and every NumPy array that views
// its values (an array keeps it alive, so no value is copied into Python).
#include <memory>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "app/run_project.h"
#include "project/project_file.h"

namespace luxgrid::python {

struct Calculation {
  project::Project project;  // after the lighting scene and the quality were applied
  app::RunOutcome outcome;   // results, checks, the scene's and the plan's warnings
  // The outputs' warnings (a plot that could not show every point), once write_outputs ran.
  std::vector<std::string> output_warnings;
  // When the calculation ran, in seconds on the clock of Python's time.monotonic() (both are
  // CLOCK_MONOTONIC): which runs overlapped in time.
  double started_s = 0.0, finished_s = 0.0;
};

using CalculationPtr = std::shared_ptr<const Calculation>;

// The Results and Surface classes of the module.
void bind_results(pybind11::module_& m);

// results.json of the calculation, byte for byte what `luxgrid calc` writes (report/
// results_document, report/results_json), but for the outputs' warnings before write_outputs.
std::string results_json_text(const Calculation& c);

}  // namespace luxgrid::python
