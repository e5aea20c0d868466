#include "report/requirements.h"

#include <cmath>
#include <cstdio>

#include "calc/json_reader.h"
#include "util/error.h"

namespace luxgrid::report {

namespace {

constexpr const char* kQuantities[] = {"Em", "U0", "Emin", "Emax", "UGR_L"};

bool known_quantity(const std::string& q) {
  for (const char* k : kQuantities) {
    if (q == k) return true;
  }
  return false;
}

// UGR_L on an observers surface without any luminaire in any view: nothing glares, the check
// is met with an achieved value of 0 (docs/glare.md).
double achieved_value(const calc::SurfaceResult& r, const std::string& q) {
  if (q == "UGR_L") return r.UGR_max.value_or(0.0);
  const calc::Statistics& s = r.stats;
  if (q == "Em") return s.Eavg;
  if (q == "U0") return s.U0;
  if (q == "Emin") return s.Emin;
  return s.Emax;
}

const char* unit_of(const std::string& q) { return q == "U0" || q == "UGR_L" ? "" : " lx"; }

}  // namespace

Requirements parse_requirements(const nlohmann::json& project, const std::string& label) {
  Requirements out;
  if (!project.is_object() || !project.contains("surfaces") || !project["surfaces"].is_array()) return out;
  const calc::JsonValue surfaces(project["surfaces"], label, "/surfaces");
  for (const auto& s : surfaces.items()) {
    if (!s.is_object() || !s.has("requirements")) continue;
    const auto req = s.at("requirements");
    if (!req.is_object()) req.fail("expected an object such as {\"Em\": 500, \"U0\": 0.6}, got " + calc::json_type_name(req.raw()));
    const std::string name = s.has("name") && s.at("name").is_string() ? s.at("name").as_string() : "";
    if (name.empty()) s.at("name").fail("expected the surface's name");
    auto& limits = out[name];
    for (const auto& [key, _] : req.raw().items()) {
      const auto v = req.at(key.c_str());
      if (!known_quantity(key)) {
        v.fail("unknown quantity \"" + key + "\", expected Em, U0, Emin or Emax");
      }
      if (key == "UGR_L" && !s.has("observers")) {
        v.fail("UGR_L (the largest UGR allowed) needs an observers surface: UGR is computed at "
               "observer positions (\"observers\": [{\"at\": ..., \"directions\": ...}])");
      }
      const double limit = key == "U0" ? v.as_number_in(0.0, 1.0) : v.as_non_negative();
      if (!(limit > 0.0)) v.fail("expected a positive number, got " + v.raw().dump());
      limits[key] = limit;
    }
  }
  return out;
}

nlohmann::json without_requirements(const nlohmann::json& project) {
  nlohmann::json out = project;
  if (out.is_object() && out.contains("surfaces") && out["surfaces"].is_array()) {
    for (auto& s : out["surfaces"]) {
      if (s.is_object()) s.erase("requirements");
    }
  }
  return out;
}

std::vector<RequirementCheck> check_requirements(const calc::Results& results, const Requirements& req) {
  std::vector<RequirementCheck> checks;
  for (const auto& [name, _] : req) {
    bool found = false;
    for (const auto& s : results.surfaces) found = found || s.grid.name == name;
    if (!found) throw InputError("requirements: no calculation surface named \"" + name + "\"");
  }
  for (const auto& s : results.surfaces) {
    const auto it = req.find(s.grid.name);
    if (it == req.end()) continue;
    for (const char* q : kQuantities) {
      const auto lim = it->second.find(q);
      if (lim == it->second.end()) continue;
      RequirementCheck c;
      c.surface = s.grid.name;
      c.quantity = q;
      c.required = lim->second;
      c.achieved = achieved_value(s, q);
      c.upper_limit = c.quantity == "Emax" || c.quantity == "UGR_L";
      c.margin = c.upper_limit ? c.required - c.achieved : c.achieved - c.required;
      c.margin_rel = c.margin / c.required;
      c.met = c.margin >= -kAtLimitRelTol * c.required;
      checks.push_back(c);
    }
  }
  return checks;
}

bool all_met(const std::vector<RequirementCheck>& checks) {
  for (const auto& c : checks) {
    if (!c.met) return false;
  }
  return true;
}

nlohmann::json check_to_json(const RequirementCheck& c) {
  return {{"quantity", c.quantity}, {"limit", c.upper_limit ? "max" : "min"}, {"required", c.required},
          {"achieved", c.achieved}, {"met", c.met}, {"margin", c.margin}, {"margin_rel", c.margin_rel}};
}

std::string format_checks(const std::vector<RequirementCheck>& checks) {
  std::string out;
  char line[300];
  for (const auto& c : checks) {
    const char* unit = unit_of(c.quantity);
    std::snprintf(line, sizeof line, "%-20s %-4s required %s %g%s  achieved %.4g%s  %s (%+.4g%s, %+.1f %%)\n",
                  c.surface.c_str(), c.quantity.c_str(), c.upper_limit ? "<=" : ">=", c.required, unit,
                  c.achieved, unit, c.met ? "met" : "NOT MET", c.margin, unit, 100.0 * c.margin_rel);
    out += line;
  }
  return out;
}

}  // namespace luxgrid::report
