#include "app/validation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>

#include "app/run_project.h"
#include "calc/plan_estimates.h"
#include "calc/statistics.h"
#include "project/json_reader.h"
#include "project/safe_json.h"
#include "util/error.h"

namespace luxgrid::app {

namespace fs = std::filesystem;

namespace {

const calc::SurfaceResult& find_surface(const project::JsonValue& where, const calc::Results& r,
                                        const std::string& name) {
  for (const auto& s : r.surfaces) {
    if (s.grid.name == name) return s;
  }
  where.fail("the case has no surface named \"" + name + "\"");
}

// The values of `quantity` ("E", "E_direct", "E_indirect", or in the daylight scene "DF", "SC",
// "ERC") over the surface's points.
const std::vector<double>& quantity_values(const project::JsonValue& where,
                                           const calc::SurfaceResult& s,
                                           const std::string& quantity) {
  if (quantity == "E") return s.E;
  if (quantity == "E_direct") return s.E_direct;
  if (quantity == "E_indirect") return s.E_indirect;
  if (quantity == "DF" && !s.DF.empty()) return s.DF;
  if (quantity == "SC" && !s.SC.empty()) return s.SC;
  if (quantity == "ERC" && !s.ERC.empty()) return s.ERC;
  where.fail(
      "expected quantity \"E\", \"E_direct\" or \"E_indirect\" (or in the daylight scene \"DF\", "
      "\"SC\" or \"ERC\"), got \"" +
      quantity + "\"");
}

double point_value(const project::JsonValue& where, const calc::SurfaceResult& s, size_t index,
                   const std::vector<double>& values) {
  if (index >= values.size()) {
    where.fail("point " + std::to_string(index) + " is out of range: surface \"" + s.grid.name +
               "\" has " + std::to_string(values.size()) + " points");
  }
  return values[index];
}

// A statistic of `values` over the surface's active points.
double stat_value(const project::JsonValue& where, const calc::SurfaceResult& s,
                  const std::vector<double>& values, const std::string& stat) {
  const calc::Statistics st = calc::compute_statistics(values, s.grid.active);
  if (stat == "Emin") return st.Emin;
  if (stat == "Eavg") return st.Eavg;
  if (stat == "Emax") return st.Emax;
  if (stat == "U0") return st.U0;
  if (stat == "Ud") return st.Ud;
  where.fail("expected stat \"Emin\", \"Eavg\", \"Emax\", \"U0\" or \"Ud\", got \"" + stat + "\"");
}

// Glare quantities of an observers surface (calc/glare): "UGR" and "Lb" of view `point` (views
// numbered over all observers in order, like the surface's points), and "L", "omega" and "p" of
// that view's term `term` (the counted luminaires in the scene's order).
bool is_glare_quantity(const std::string& q) {
  return q == "UGR" || q == "Lb" || q == "L" || q == "omega" || q == "p";
}

double glare_value(const project::JsonValue& where, const calc::SurfaceResult& s, size_t view,
                   const std::optional<project::JsonValue>& term, const std::string& q) {
  if (s.grid.kind != geometry::SurfaceGrid::Kind::observers) {
    where.fail("quantity \"" + q + "\" needs an observers surface; \"" + s.grid.name +
               "\" is not one");
  }
  size_t k = 0;
  for (const auto& o : s.observers)
    for (const auto& v : o.views) {
      if (k++ != view) continue;
      if (q == "UGR") {
        if (!v.UGR)
          where.fail("view " + std::to_string(view) + " has no luminaire in its field: no UGR");
        return *v.UGR;
      }
      if (q == "Lb") return v.Lb_cd_m2;
      if (!term)
        where.fail("quantity \"" + q + "\" needs \"term\": the index of a counted luminaire");
      const int t = term->as_int();
      if (t < 0 || static_cast<size_t>(t) >= v.terms.size()) {
        term->fail("term " + std::to_string(t) + " is out of range: the view counts " +
                   std::to_string(v.terms.size()) + " luminaires");
      }
      const auto& g = v.terms[static_cast<size_t>(t)].term;
      return q == "L" ? g.L_cd_m2 : q == "omega" ? g.omega_sr : g.p;
    }
  where.fail("view " + std::to_string(view) + " is out of range: surface \"" + s.grid.name +
             "\" has " + std::to_string(k) + " views");
}

// A check's relative tolerance at `quality`: a check held to standard's promise or tighter is
// held to the quality's promise where that is tighter; a looser one (its README says why: the
// reference's own uncertainty, a rounded printed value) keeps its own.
double relative_tolerance_at(double rel_tol, std::optional<calc::Quality> quality) {
  if (!quality) return rel_tol;
  const double standard = calc::promised_error(calc::Quality::standard);
  return rel_tol <= standard ? std::min(rel_tol, calc::promised_error(*quality)) : rel_tol;
}

void check_case(const fs::path& dir, const fs::path& out_dir, std::optional<calc::Quality> quality,
                ValidationReport& report) {
  const std::string name = dir.filename().string();
  const fs::path expected_file = dir / "expected.json";
  const nlohmann::json doc =
      project::read_json_file(expected_file, project::kMaxProjectFileBytes, "expected-values file");
  const project::JsonDocument document(doc, name + "/expected.json");
  const project::JsonValue root = document.root();
  root.expect_object();
  root.accept_any("notes");
  // One run per sky the cases ask for (a daylight case's "sky": the project under each of the
  // CIE skies); "" is the project as it is.
  std::map<std::string, RunOutcome> runs;
  const auto outcome_for = [&](const std::string& sky) -> const RunOutcome& {
    auto it = runs.find(sky);
    if (it != runs.end()) return it->second;
    RunOptions options;
    options.quality = quality;
    if (!sky.empty()) options.daylight_sky = sky, options.report = false;
    RunOutcome outcome = run_project(
        dir / "project.json", out_dir / (sky.empty() ? name : name + "_sky_" + sky), options);
    // On stderr, as every command prints its warnings; the table on stdout stays the table.
    for (const auto& w : outcome.warnings)
      std::fprintf(stderr, "luxgrid: warning: case %s: %s\n", name.c_str(), w.c_str());
    return runs.emplace(sky, std::move(outcome)).first->second;
  };
  for (const auto& c : root.at("cases").items()) {
    c.expect_object();
    std::string sky;
    if (auto k = c.find("sky")) sky = k->is_number() ? std::to_string(k->as_int()) : k->as_string();
    const RunOutcome& outcome = outcome_for(sky);
    const auto surface_v = c.at("surface");
    const auto& s = find_surface(surface_v, outcome.results, surface_v.as_string());
    CheckRow row;
    row.case_name = name;
    row.source = c.at("source").as_string();
    row.expected = c.at("expected").as_number();
    if (c.has("point") == c.has("stat")) c.fail("expected exactly one of \"point\" or \"stat\"");
    const std::string quantity = c.has("quantity") ? c.at("quantity").as_string() : "E";
    if (is_glare_quantity(quantity)) {
      const auto p = c.at("point");
      const int index = p.as_int();
      if (index < 0) p.fail("expected a view index >= 0");
      row.got = glare_value(p, s, static_cast<size_t>(index), c.find("term"), quantity);
      row.quantity = s.grid.name + "[" + std::to_string(index) + "]." + quantity +
                     (c.has("term") ? "[" + std::to_string(c.at("term").as_int()) + "]" : "");
    } else if (c.has("stat") && c.at("stat").as_string() == "UGR_max") {
      if (!s.UGR_max) c.at("stat").fail("surface \"" + s.grid.name + "\" has no UGR_max");
      row.got = *s.UGR_max;
      row.quantity = s.grid.name + ".UGR_max";
    } else {
      const auto& values = quantity_values(c.has("quantity") ? c.at("quantity") : c, s, quantity);
      if (auto p = c.find("point")) {
        const int index = p->as_int();
        if (index < 0) p->fail("expected a point index >= 0");
        row.got = point_value(*p, s, static_cast<size_t>(index), values);
        row.quantity = s.grid.name + "[" + std::to_string(index) + "]." + quantity +
                       (sky.empty() ? "" : " (sky " + sky + ")");
      } else {
        const auto st = c.at("stat");
        row.got = stat_value(st, s, values, st.as_string());
        row.quantity = s.grid.name + "." + st.as_string() + "(" + quantity + ")";
      }
    }
    const double rel =
        relative_tolerance_at(c.has("rel_tol") ? c.at("rel_tol").as_non_negative() : 0.0, quality);
    const double abs = c.has("abs_tol") ? c.at("abs_tol").as_non_negative() : 0.0;
    if (!c.has("rel_tol") && !c.has("abs_tol")) c.fail("expected \"rel_tol\" and/or \"abs_tol\"");
    row.tolerance = std::max(rel * std::abs(row.expected), abs);
    char tol[64];
    if (c.has("rel_tol") && c.has("abs_tol"))
      std::snprintf(tol, sizeof tol, "%g %% or %g", rel * 100, abs);
    else if (c.has("rel_tol"))
      std::snprintf(tol, sizeof tol, "%g %%", rel * 100);
    else
      std::snprintf(tol, sizeof tol, "%g abs", abs);
    row.tolerance_text = tol;
    row.error = row.expected != 0.0 ? (row.got - row.expected) / std::abs(row.expected)
                                    : row.got - row.expected;
    row.pass = std::isfinite(row.got) && std::abs(row.got - row.expected) <= row.tolerance;
    c.report_unqueried();
    report.rows.push_back(row);
  }
  root.report_unqueried();
}

}  // namespace

bool ValidationReport::all_passed() const {
  if (!case_errors.empty() || rows.empty()) return false;
  return std::all_of(rows.begin(), rows.end(), [](const CheckRow& r) { return r.pass; });
}

std::string ValidationReport::markdown() const {
  std::string md =
      "| case | quantity | expected | got | error | tolerance | result | source |\n"
      "|---|---|---|---|---|---|---|---|\n";
  char line[1024];
  for (const auto& r : rows) {
    std::snprintf(line, sizeof line, "| %s | %s | %.6g | %.6g | %+.3g %% | %s | %s | %s |\n",
                  r.case_name.c_str(), r.quantity.c_str(), r.expected, r.got, r.error * 100.0,
                  r.tolerance_text.c_str(), r.pass ? "PASS" : "FAIL", r.source.c_str());
    md += line;
  }
  for (const auto& e : case_errors) md += "\nERROR: " + e + "\n";
  for (const auto& p : pending) md += "\nPENDING (not run): " + p + "\n";
  if (quality)
    md += std::string("\nEvery case run at quality ") + calc::to_string(*quality) +
          ", its checks held to the quality's promise (docs/validation.md).\n";
  return md;
}

nlohmann::json ValidationReport::json() const {
  nlohmann::json j;
  j["passed"] = all_passed();
  j["checks"] = nlohmann::json::array();
  for (const auto& r : rows) {
    j["checks"].push_back({{"case", r.case_name},
                           {"quantity", r.quantity},
                           {"expected", r.expected},
                           {"got", r.got},
                           {"error", r.error},
                           {"tolerance", r.tolerance},
                           {"tolerance_text", r.tolerance_text},
                           {"pass", r.pass},
                           {"source", r.source}});
  }
  j["case_errors"] = case_errors;
  j["pending"] = pending;
  if (quality) j["quality"] = calc::to_string(*quality);
  return j;
}

ValidationReport run_validation(const fs::path& cases_dir, const fs::path& out_dir,
                                std::optional<calc::Quality> quality) {
  if (!fs::is_directory(cases_dir))
    throw InputError(SourceLocation{cases_dir.string()}, "not a folder of cases");
  std::vector<fs::path> dirs;
  for (const auto& entry : fs::directory_iterator(cases_dir)) {
    if (entry.is_directory() && fs::exists(entry.path() / "expected.json") &&
        fs::exists(entry.path() / "project.json")) {
      dirs.push_back(entry.path());
    }
  }
  std::sort(dirs.begin(), dirs.end());
  ValidationReport report;
  report.quality = quality;
  if (fs::is_directory(cases_dir / "pending")) {
    for (const auto& entry : fs::directory_iterator(cases_dir / "pending")) {
      if (!entry.is_directory()) continue;
      std::string why;
      std::ifstream reason(entry.path() / "PENDING");
      std::getline(reason, why);
      report.pending.push_back(entry.path().filename().string() + (why.empty() ? "" : ": " + why));
    }
    std::sort(report.pending.begin(), report.pending.end());
  }
  if (dirs.empty())
    throw InputError(SourceLocation{cases_dir.string()},
                     "no case folders (project.json + expected.json)");
  for (const auto& d : dirs) {
    try {
      check_case(d, out_dir, quality, report);
    } catch (const InputError& e) {
      report.case_errors.push_back(d.filename().string() + ": " + e.what());
    } catch (const CalculationError& e) {
      report.case_errors.push_back(d.filename().string() + ": calculation failed: " + e.what());
    }
  }
  return report;
}

}  // namespace luxgrid::app
