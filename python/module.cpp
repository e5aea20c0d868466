// The compiled part of the Python package `luxgrid` (docs/python.md): a thin layer over the
// library, the same functions `luxgrid calc`, `report` and `info` call (app/run_project,
// report/write_outputs, cli/photometry_info). The pure Python part (luxgrid/__init__.py, the
// sweep) lies beside it in the package folder.
#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <tbb/global_control.h>

#include "app/run_project.h"
#include "cli/photometry_info.h"
#include "cli/threads.h"
#include "project/project_file.h"
#include "project/safe_json.h"
#include "python/calculation.h"
#include "python/json_python.h"
#include "report/output_folder.h"
#include "util/error.h"
#include "util/process_setup.h"

namespace py = pybind11;
using namespace luxgrid;

namespace {

// The exception classes, created at import (luxgrid.InputError, luxgrid.CalculationError).
PyObject* input_error_type = nullptr;
PyObject* calculation_error_type = nullptr;

// The thread limit set by set_threads (or LUXGRID_THREADS at import): the CLI's --threads, for
// the whole process (cli/threads.h). Null: every core.
std::unique_ptr<tbb::global_control> thread_limit;
std::optional<int> thread_count;

void set_threads(std::optional<int> n) {
  if (n && (*n < 1 || *n > cli::kMaxThreads))
    throw InputError("threads: expected a whole number from 1 to " +
                     std::to_string(cli::kMaxThreads) + ", got " + std::to_string(*n));
  thread_limit.reset();
  thread_limit = cli::limit_threads(n);
  thread_count = n;
}

double monotonic_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

app::RunOptions run_options(const std::optional<std::string>& quality,
                            const std::optional<std::string>& scene) {
  app::RunOptions options;
  if (quality) {
    options.quality = calc::quality_from_string(*quality);
    if (!options.quality)
      throw InputError("quality: expected draft, standard, high or reference, got \"" + *quality +
                       "\"");
  }
  if (scene) {
    if (*scene != "normal" && *scene != "emergency")
      throw InputError("scene: expected normal or emergency, got \"" + *scene + "\"");
    options.scene =
        *scene == "emergency" ? calc::LightingScene::emergency : calc::LightingScene::normal;
  }
  return options;
}

// Loads (`load` returns the project), prepares and calculates, the GIL released throughout.
template <class Load>
std::shared_ptr<python::Calculation> calculate(Load load, const app::RunOptions& options) {
  auto c = std::make_shared<python::Calculation>();
  py::gil_scoped_release release;
  c->started_s = monotonic_s();
  const auto t0 = std::chrono::steady_clock::now();
  app::start_worker_threads();
  c->project = load();
  app::prepare_project(c->project, options);
  const double load_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  c->outcome = app::calculate_project(c->project, options, load_s);
  c->finished_s = monotonic_s();
  return c;
}

// A project given as text (a dict, dumped by the Python side): named `label` in messages, its
// relative photometry paths resolved against `base_dir`, as a file named `label` in `base_dir`
// would be (docs/python.md, "Projects as dicts"). Its messages give the JSON pointer but no line
// and column: those of the dumped text would point nowhere the user wrote.
project::Project parse_text(const std::string& text, const std::string& label,
                            const std::string& base_dir) {
  project::Project p =
      project::parse_project(project::parse_json_text(text, label), label, base_dir);
  p.scene.project_file = std::filesystem::path(base_dir) / label;
  return p;
}

}  // namespace

PYBIND11_MODULE(_luxgrid, m) {
  // The product's allocator settings (util/process_setup.h), as the CLI has them.
  set_up_process();
  m.attr("__version__") = LUXGRID_VERSION;

  // InputError(ValueError) and CalculationError(RuntimeError), each with the CLI's message as
  // str(e); InputError also with its place as attributes (None where not known).
  input_error_type = PyErr_NewExceptionWithDoc(
      "luxgrid.InputError",
      "Bad input: str(e) is the CLI's message; .file, .line, .column, .pointer its place "
      "(None where not known), .message the message without it.",
      PyExc_ValueError, nullptr);
  calculation_error_type = PyErr_NewExceptionWithDoc("luxgrid.CalculationError",
                                                     "A calculation that could not be completed.",
                                                     PyExc_RuntimeError, nullptr);
  m.attr("InputError") = py::handle(input_error_type);
  m.attr("CalculationError") = py::handle(calculation_error_type);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      const SourceLocation& w = e.where();
      py::object error = py::handle(input_error_type)(e.what());
      error.attr("file") = w.file.empty() ? py::object(py::none()) : py::str(w.file);
      error.attr("line") = w.line > 0 ? py::object(py::int_(w.line)) : py::object(py::none());
      error.attr("column") = w.column > 0 ? py::object(py::int_(w.column)) : py::object(py::none());
      error.attr("pointer") = w.pointer.empty() ? py::object(py::none()) : py::str(w.pointer);
      error.attr("message") = e.message();
      PyErr_SetObject(input_error_type, error.ptr());
    } catch (const CalculationError& e) {
      PyErr_SetString(calculation_error_type, e.what());
    }
  });

  python::bind_results(m);

  m.def(
      "calc_file",
      [](const std::string& path, std::optional<std::string> quality,
         std::optional<std::string> scene) {
        const app::RunOptions options = run_options(quality, scene);
        return calculate([&] { return project::load_project(path); }, options);
      },
      py::arg("path"), py::arg("quality") = py::none(), py::arg("scene") = py::none());
  m.def(
      "calc_text",
      [](const std::string& text, const std::string& label, const std::string& base_dir,
         std::optional<std::string> quality, std::optional<std::string> scene) {
        const app::RunOptions options = run_options(quality, scene);
        return calculate([&] { return parse_text(text, label, base_dir); }, options);
      },
      py::arg("text"), py::arg("label"), py::arg("base_dir"), py::arg("quality") = py::none(),
      py::arg("scene") = py::none());
  m.def(
      "check_text",
      [](const std::string& text, const std::string& label, const std::string& base_dir) {
        std::vector<std::string> warnings;
        py::gil_scoped_release release;
        for (const auto& w : parse_text(text, label, base_dir).scene.warnings)
          warnings.push_back(w.text());
        return warnings;
      },
      "Loads a project given as text as calc_text would, and returns its warnings.");
  m.def(
      "read_project",
      [](const std::string& path) {
        // Loaded whole first, so that a bad project fails here with the CLI's message and place.
        std::vector<std::string> warnings;
        nlohmann::json doc;
        {
          py::gil_scoped_release release;
          for (const auto& w : project::load_project(path).scene.warnings)
            warnings.push_back(w.text());
          doc = project::read_json_file(path);
        }
        return py::make_tuple(python::to_python(doc), warnings);
      },
      "The document of a project file (as a dict) and its warnings, once it loads.");
  m.def(
      "info",
      [](const std::string& file, const std::vector<std::pair<double, double>>& at,
         const std::string& interpolation, bool ugr) {
        if (interpolation != "bilinear" && interpolation != "bicubic")
          throw InputError("interpolation: expected bilinear or bicubic, got \"" + interpolation +
                           "\"");
        std::vector<cli::InfoAt> directions;
        for (const auto& [c, g] : at) {
          if (!(g >= 0 && g <= 180))
            throw InputError("at: expected gamma between 0 and 180 degrees, got " +
                             std::to_string(g));
          directions.push_back({c, g});
        }
        nlohmann::json j;
        {
          py::gil_scoped_release release;
          j = cli::photometry_info_json(
              cli::read_photometry_info(file, directions, interpolation, ugr));
        }
        return python::to_python(j);
      },
      py::arg("file"), py::arg("at") = std::vector<std::pair<double, double>>{},
      py::arg("interpolation") = "bilinear", py::arg("ugr") = false);
  m.def(
      "write_outputs",
      [](python::Calculation& c, const std::string& folder, bool report, bool arrays_npy,
         bool part_plots) {
        app::RunOptions options;
        options.report = report;
        options.arrays_npy = arrays_npy;
        options.part_plots = part_plots;
        // A copy: writing adds the "report" phase and the outputs' warnings to what it writes.
        app::RunOutcome outcome = c.outcome;
        {
          py::gil_scoped_release release;
          report::OutputFolder out(folder, app::input_files(c.project.scene));
          app::write_run_outputs(outcome, c.project, out, options);
        }
        // The outputs' warnings belong to the calculation from now on (.warnings, to_json()).
        c.output_warnings.assign(outcome.warnings.begin() + c.outcome.warnings.size(),
                                 outcome.warnings.end());
        return py::make_tuple(c.output_warnings, outcome.kept);
      },
      py::arg("results"), py::arg("folder"), py::arg("report") = true,
      py::arg("arrays_npy") = false, py::arg("part_plots") = false);
  m.def("set_threads", &set_threads, py::arg("n"),
        "Caps every calculation of this process at n threads (None: every core).");
  m.def("threads", [] { return thread_count; });
  // LUXGRID_THREADS, as the CLI reads it.
  set_threads(cli::requested_threads(std::nullopt));
}
