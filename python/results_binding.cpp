// The Results and Surface classes: the values as NumPy arrays viewing the calculation's own
// vectors (read-only, no copy, no Python object per element), the rest as plain Python data made
// by the functions that write results.json.
#include <sstream>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "calc/scene.h"
#include "python/calculation.h"
#include "python/json_python.h"
#include "report/energy.h"
#include "report/luminaire_types.h"
#include "report/plan_json.h"
#include "report/requirement_checks.h"
#include "report/results_document.h"
#include "report/results_json.h"

namespace luxgrid::python {

namespace py = pybind11;

namespace {

// A surface of a calculation: the index into its results.
struct SurfaceRef {
  CalculationPtr calculation;
  std::size_t index;
  const calc::SurfaceResult& result() const { return calculation->outcome.results.surfaces[index]; }
};

// A read-only array over `data` that keeps the calculation alive as long as it lives.
py::array view(const CalculationPtr& c, const double* data, std::vector<py::ssize_t> shape,
               std::vector<py::ssize_t> strides) {
  py::capsule owner(new CalculationPtr(c), [](void* p) { delete static_cast<CalculationPtr*>(p); });
  py::array a(py::dtype::of<double>(), std::move(shape), std::move(strides), data, owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

py::array values(const CalculationPtr& c, const std::vector<double>& v) {
  return view(c, v.data(), {static_cast<py::ssize_t>(v.size())}, {sizeof(double)});
}

// Points and normals: n x 3, the Vec3s' own doubles.
static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 is three packed doubles");
py::array vectors(const CalculationPtr& c, const std::vector<Vec3>& v) {
  return view(c, v.empty() ? nullptr : &v[0].x, {static_cast<py::ssize_t>(v.size()), 3},
              {sizeof(Vec3), sizeof(double)});
}

// std::vector<bool> packs its bits: copied into a bool array (one byte a point).
py::array flags(const std::vector<bool>& v) {
  py::array_t<bool> a(static_cast<py::ssize_t>(v.size()));
  bool* out = a.mutable_data();
  for (std::size_t k = 0; k < v.size(); ++k) out[k] = v[k];
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

py::dict stats_dict(const calc::Statistics& s) {
  py::dict d;
  d["Emin"] = s.Emin;
  d["Eavg"] = s.Eavg;
  d["Emax"] = s.Emax;
  d["U0"] = s.U0;
  d["Ud"] = s.Ud;
  return d;
}

py::object optional_float(const std::optional<double>& v) {
  return v ? py::object(py::float_(*v)) : py::object(py::none());
}

}  // namespace

std::string results_json_text(const Calculation& c) {
  const calc::Scene& scene = c.project.scene;
  const calc::Results& results = c.outcome.results;
  const auto types =
      report::luminaire_types(scene, results.plan.indirect_decision.luminous_flux_lm);
  const nlohmann::json doc =
      report::results_document(results, &scene, c.outcome.checks, types, c.output_warnings,
                               LUXGRID_VERSION, c.outcome.en17037 ? &*c.outcome.en17037 : nullptr);
  std::ostringstream out;
  report::write_results_json(out, doc, results);
  return out.str();
}

void bind_results(py::module_& m) {
  py::class_<SurfaceRef>(m, "Surface",
                         "One calculation surface: its points and values as read-only NumPy "
                         "arrays (float64; active: bool), and its statistics.")
      .def_property_readonly("name", [](const SurfaceRef& s) { return s.result().grid.name; })
      .def_property_readonly(
          "kind", [](const SurfaceRef& s) { return geometry::to_string(s.result().grid.kind); })
      .def_property_readonly(
          "quantity", [](const SurfaceRef& s) { return to_string(s.result().grid.quantity); })
      .def_property_readonly("shape",
                             [](const SurfaceRef& s) {
                               const auto& g = s.result().grid;
                               return py::make_tuple(g.nu, g.nv);
                             })
      .def_property_readonly(
          "E", [](const SurfaceRef& s) { return values(s.calculation, s.result().E); })
      .def_property_readonly(
          "E_direct",
          [](const SurfaceRef& s) { return values(s.calculation, s.result().E_direct); })
      .def_property_readonly(
          "E_indirect",
          [](const SurfaceRef& s) { return values(s.calculation, s.result().E_indirect); })
      .def_property_readonly(
          "points",
          [](const SurfaceRef& s) { return vectors(s.calculation, s.result().grid.points); })
      .def_property_readonly(
          "normals",
          [](const SurfaceRef& s) { return vectors(s.calculation, s.result().grid.normals); })
      .def_property_readonly("active",
                             [](const SurfaceRef& s) { return flags(s.result().grid.active); })
      .def_property_readonly("stats",
                             [](const SurfaceRef& s) { return stats_dict(s.result().stats); })
      .def_property_readonly("UGR_max",
                             [](const SurfaceRef& s) { return optional_float(s.result().UGR_max); })
      .def("__repr__", [](const SurfaceRef& s) {
        return "<luxgrid.Surface '" + s.result().grid.name + "', " +
               std::to_string(s.result().E.size()) + " points>";
      });

  py::class_<Calculation, std::shared_ptr<Calculation>>(
      m, "Results", "What a calculation produced (docs/python.md, \"Results\").")
      .def_property_readonly("project",
                             [](const Calculation& c) { return c.outcome.results.project; })
      .def_property_readonly(
          "quality",
          [](const Calculation& c) { return calc::to_string(c.outcome.results.quality); })
      .def_property_readonly(
          "scene", [](const Calculation& c) { return calc::to_string(c.outcome.results.scene); })
      .def_property_readonly(
          "maintenance_factor",
          [](const Calculation& c) { return c.outcome.results.maintenance_factor; })
      .def_property_readonly("surfaces",
                             [](const std::shared_ptr<Calculation>& c) {
                               py::dict d;
                               const auto& surfaces = c->outcome.results.surfaces;
                               for (std::size_t k = 0; k < surfaces.size(); ++k)
                                 d[py::str(surfaces[k].grid.name)] = SurfaceRef{c, k};
                               return d;
                             })
      .def_property_readonly("stats",
                             [](const Calculation& c) {
                               py::dict d;
                               for (const auto& s : c.outcome.results.surfaces)
                                 d[py::str(s.grid.name)] = stats_dict(s.stats);
                               return d;
                             })
      .def_property_readonly("requirements",
                             [](const Calculation& c) {
                               py::list out;
                               for (const auto& check : c.outcome.checks) {
                                 nlohmann::json j = report::check_to_json(check);
                                 j["surface"] = check.surface;
                                 out.append(to_python(j));
                               }
                               return out;
                             })
      .def_property_readonly("requirements_met",
                             [](const Calculation& c) -> py::object {
                               if (c.outcome.checks.empty()) return py::none();
                               return py::bool_(report::all_met(c.outcome.checks));
                             })
      .def_property_readonly("plan",
                             [](const Calculation& c) {
                               return to_python(report::plan_to_json(c.outcome.results.plan));
                             })
      .def_property_readonly("warnings",
                             [](const Calculation& c) {
                               std::vector<std::string> all = c.outcome.warnings;
                               all.insert(all.end(), c.output_warnings.begin(),
                                          c.output_warnings.end());
                               return all;
                             })
      .def_property_readonly("timing",
                             [](const Calculation& c) {
                               py::dict d;
                               for (const auto& [phase, s] : c.outcome.results.timing_s)
                                 d[py::str(phase)] = s;
                               return d;
                             })
      .def_property_readonly(
          "run_interval",
          [](const Calculation& c) { return py::make_tuple(c.started_s, c.finished_s); })
      .def_property_readonly(
          "energy",
          [](const Calculation& c) {
            const calc::Scene& scene = c.project.scene;
            const calc::Results& results = c.outcome.results;
            const auto types =
                report::luminaire_types(scene, results.plan.indirect_decision.luminous_flux_lm);
            py::list out;
            for (const auto& e : report::room_energy(scene, types, results, c.outcome.checks)) {
              py::dict d;
              d["room"] = e.room;
              d["area_m2"] = e.area_m2;
              d["luminaires"] = e.luminaires;
              d["power_W"] = optional_float(e.power_W);
              d["W_per_m2"] = optional_float(e.W_per_m2());
              d["reference_surface"] = e.reference_surface;
              d["Eavg_lx"] = optional_float(e.Eavg_lx);
              d["W_per_m2_per_100lx"] = optional_float(e.W_per_m2_per_100lx());
              out.append(std::move(d));
            }
            return out;
          })
      .def(
          "to_json",
          [](const Calculation& c) {
            std::string text;
            {
              py::gil_scoped_release release;
              text = results_json_text(c);
            }
            return text;
          },
          "results.json as `luxgrid calc` writes it (docs/python.md)")
      .def(
          "to_dict",
          [](const Calculation& c) {
            std::string text;
            {
              py::gil_scoped_release release;
              text = results_json_text(c);
            }
            // Python's own parser: every number read back as the double results.json holds.
            return py::module_::import("json").attr("loads")(text);
          },
          "results.json as `luxgrid calc` writes it, parsed")
      .def("__repr__", [](const Calculation& c) {
        return "<luxgrid.Results of '" + c.outcome.results.project + "', " +
               std::to_string(c.outcome.results.surfaces.size()) + " surfaces>";
      });
}

}  // namespace luxgrid::python
