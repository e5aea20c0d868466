#include "report/requirement_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "report/en17037_checks.h"
#include "util/error.h"
#include "util/format.h"

namespace luxgrid::report {

namespace {

// In the order checks are listed.
constexpr const char* kQuantities[] = {"Em",  "U0",        "Emin",  "Emax", "Ez",
                                       "Esc", "modelling", "UGR_L", "Ra"};

bool is_one_of(const std::string& key, std::initializer_list<const char*> keys) {
  for (const char* k : keys) {
    if (key == k) return true;
  }
  return false;
}

struct Achieved {
  bool calculated = true;
  double value = 0.0;
  std::optional<double> value_max;
  std::string note;
};

const calc::SurfaceResult& surface_named(const calc::Results& results, const std::string& name) {
  for (const auto& s : results.surfaces) {
    if (s.grid.name == name) return s;
  }
  throw InputError("requirements: no calculation surface named \"" + name + "\"");
}

// Ez / Eh at each active point of two surfaces built on the same points.
Achieved modelling_ratio(const calc::SurfaceResult& cyl, const calc::SurfaceResult& hor) {
  const auto& a = cyl.grid;
  const auto& b = hor.grid;
  if (a.points.size() != b.points.size()) {
    throw InputError("requirements: modelling pairs \"" + a.name + "\" (" +
                     std::to_string(a.points.size()) + " points) with \"" + b.name + "\" (" +
                     std::to_string(b.points.size()) +
                     " points); they must be the same grid, once cylindrical and once horizontal");
  }
  Achieved out;
  out.value = std::numeric_limits<double>::infinity();
  out.value_max = -std::numeric_limits<double>::infinity();
  size_t used = 0, dark = 0;
  for (size_t i = 0; i < a.points.size(); ++i) {
    if (glm::length(a.points[i] - b.points[i]) > kModellingPairTolerance_m) {
      throw InputError(
          "requirements: modelling pairs \"" + a.name + "\" with \"" + b.name +
          "\", but their point " + std::to_string(i) +
          " differs; they must be the same grid, once cylindrical and once horizontal");
    }
    const bool on = (i >= a.active.size() || a.active[i]) && (i >= b.active.size() || b.active[i]);
    if (!on) continue;
    if (!(hor.E[i] > 0.0)) {  // no horizontal light: the ratio is undefined, not infinite
      ++dark;
      continue;
    }
    const double ratio = cyl.E[i] / hor.E[i];
    out.value = std::min(out.value, ratio);
    out.value_max = std::max(*out.value_max, ratio);
    ++used;
  }
  if (used == 0) {
    return {false, 0.0, std::nullopt, "no point of \"" + b.name + "\" receives horizontal light"};
  }
  out.note =
      "Ez / Eh over " + std::to_string(used) + " points of \"" + a.name + "\" / \"" + b.name + "\"";
  if (dark) out.note += " (" + std::to_string(dark) + " without horizontal light left out)";
  return out;
}

Achieved achieved_value(const calc::Results& results, const calc::SurfaceResult& s,
                        const SurfaceRequirements& r, const std::string& q,
                        const ComplianceInputs& inputs) {
  const auto& st = s.stats;
  if (q == "Em") return {true, st.Eavg, std::nullopt, ""};
  if (q == "U0") return {true, st.U0, std::nullopt, ""};
  if (q == "Emin") return {true, st.Emin, std::nullopt, ""};
  if (q == "Emax") return {true, st.Emax, std::nullopt, ""};
  if (q == "Esc") return {true, st.Eavg, std::nullopt, ""};
  if (q == "Ez") {
    if (s.grid.quantity == geometry::Quantity::cylindrical)
      return {true, st.Eavg, std::nullopt, ""};
    if (r.cylindrical.empty()) {
      return {false, 0.0, std::nullopt,
              "no cylindrical surface named (\"cylindrical\": \"<surface>\")"};
    }
    return {true, surface_named(results, r.cylindrical).stats.Eavg, std::nullopt,
            "Eavg of \"" + r.cylindrical + "\""};
  }
  if (q == "modelling") {
    if (s.grid.quantity == geometry::Quantity::cylindrical)
      return modelling_ratio(s, surface_named(results, r.horizontal));
    return modelling_ratio(surface_named(results, r.cylindrical), s);
  }
  if (q == "UGR_L") {
    // An observers surface whose views see no luminaire has no UGR_max: nothing glares there, so
    // it counts as UGR 0 (docs/glare.md); any other surface gives no UGR at all.
    std::optional<double> worst;
    std::string from;
    auto take = [&](const calc::SurfaceResult& o) {
      const double ugr = o.UGR_max.value_or(0.0);
      if (!worst || ugr > *worst) {
        worst = ugr;
        from = o.grid.name;
      }
    };
    const auto is_observers = [](const calc::SurfaceResult& o) {
      return o.grid.kind == geometry::SurfaceGrid::Kind::observers;
    };
    if (!r.glare_observers.empty()) {
      for (const auto& name : r.glare_observers) {
        const auto& o = surface_named(results, name);
        if (!is_observers(o))
          return {false, 0.0, std::nullopt,
                  "surface \"" + name + "\" gives no UGR (not an observers surface)"};
        take(o);
      }
    } else {
      for (const auto& o : results.surfaces) {
        if (is_observers(o)) take(o);
      }
    }
    if (!worst) return {false, 0.0, std::nullopt, "no observers surface computes UGR"};
    return {true, *worst, std::nullopt, "largest UGR of \"" + from + "\""};
  }
  // Ra
  if (!inputs.Ra)
    return {false, 0.0, std::nullopt, inputs.Ra_source.empty() ? "unknown" : inputs.Ra_source};
  return {true, *inputs.Ra, std::nullopt, inputs.Ra_source};
}

void check_surface(const calc::Results& results, const calc::SurfaceResult& s,
                   const SurfaceRequirements& r, const ComplianceInputs& inputs,
                   std::vector<RequirementCheck>& checks) {
  for (const char* q : kQuantities) {
    const bool is_modelling = std::string(q) == "modelling";
    const auto lim = r.limits.find(q);
    if (is_modelling ? !r.modelling : lim == r.limits.end()) continue;
    RequirementCheck c;
    c.surface = s.grid.name;
    c.role = r.role;
    c.quantity = q;
    c.required = is_modelling ? r.modelling->first : lim->second;
    if (is_modelling) c.required_max = r.modelling->second;
    const auto src = r.from_preset.find(q);
    if (src != r.from_preset.end()) c.source = src->second;
    c.upper_limit = c.quantity == "Emax" || c.quantity == "UGR_L";
    const Achieved a = achieved_value(results, s, r, q, inputs);
    c.calculated = a.calculated;
    c.note = a.note;
    if (c.calculated) {
      c.achieved = a.value;
      c.achieved_max = a.value_max;
      if (is_modelling) {
        c.margin = std::min(c.achieved - c.required, *c.required_max - *c.achieved_max);
      } else {
        c.margin = c.upper_limit ? c.required - c.achieved : c.achieved - c.required;
      }
      c.margin_rel = c.margin / c.required;
      c.met = c.margin >= -kAtLimitRelTol * c.required;
    }
    checks.push_back(c);
  }
}

}  // namespace

std::string requirement_unit(const std::string& q) {
  // EN 17037's checks (report/en17037_checks.h): shares of the reference plane.
  if (is_one_of(q, {kEn17037TargetQuantity, kEn17037MinimumTargetQuantity})) return " %";
  return is_one_of(q, {"Em", "Emin", "Emax", "Ez", "Esc"}) ? " lx" : "";
}

std::vector<RequirementCheck> check_requirements(const calc::Results& results,
                                                 const Requirements& req,
                                                 const ComplianceInputs& inputs) {
  std::vector<RequirementCheck> checks;
  for (const auto& [name, _] : req.surfaces) surface_named(results, name);
  for (const auto& [entry, _] : req.walls) {
    bool found = false;
    for (const auto& s : results.surfaces)
      found = found || s.grid.name.rfind(entry + " wall ", 0) == 0;
    if (!found)
      throw InputError("requirements: room_surfaces \"" + entry + "\" gave no wall grids");
  }
  for (const auto& s : results.surfaces) {
    const auto it = req.surfaces.find(s.grid.name);
    if (it != req.surfaces.end()) check_surface(results, s, it->second, inputs, checks);
    for (const auto& [entry, walls] : req.walls) {
      // "<entry> wall <k>": the walls of that room_surfaces entry, each checked on its own.
      const std::string prefix = entry + " wall ";
      if (s.grid.name.rfind(prefix, 0) == 0 &&
          s.grid.name.find_first_not_of("0123456789", prefix.size()) == std::string::npos &&
          s.grid.name.size() > prefix.size()) {
        check_surface(results, s, walls, inputs, checks);
      }
    }
  }
  return checks;
}

bool all_met(const std::vector<RequirementCheck>& checks) {
  for (const auto& c : checks) {
    if (!c.calculated || !c.met) return false;
  }
  return true;
}

nlohmann::json check_to_json(const RequirementCheck& c) {
  nlohmann::json j = {{"quantity", c.quantity},
                      {"role", c.role},
                      {"limit", c.required_max  ? "range"
                                : c.upper_limit ? "max"
                                                : "min"},
                      {"required", c.required},
                      {"calculated", c.calculated},
                      {"met", c.met}};
  if (c.required_max) j["required_max"] = *c.required_max;
  if (c.calculated) {
    j["achieved"] = c.achieved;
    if (c.achieved_max) j["achieved_max"] = *c.achieved_max;
    j["margin"] = c.margin;
    j["margin_rel"] = c.margin_rel;
  } else {
    j["achieved"] = nullptr;
  }
  if (!c.source.empty()) j["source"] = c.source;
  if (!c.note.empty()) j["note"] = c.note;
  return j;
}

std::string format_checks(const std::vector<RequirementCheck>& checks) {
  std::string out;
  char line[600];
  for (const auto& c : checks) {
    const std::string unit = requirement_unit(c.quantity);
    const std::string required =
        c.required_max
            ? format_double("%g", c.required) + " to " + format_double("%g", *c.required_max)
            : std::string(c.upper_limit ? "<= " : ">= ") + format_double("%g", c.required) + unit;
    if (!c.calculated) {
      std::snprintf(line, sizeof line, "%-20s %-9s required %s  NOT CALCULATED (%s)\n",
                    c.surface.c_str(), c.quantity.c_str(), required.c_str(), c.note.c_str());
    } else {
      const std::string achieved = c.achieved_max ? format_double("%.3g", c.achieved) + " to " +
                                                        format_double("%.3g", *c.achieved_max)
                                                  : format_double("%.4g", c.achieved) + unit;
      std::snprintf(line, sizeof line,
                    "%-20s %-9s required %s  achieved %s  %s (%+.4g%s, %+.1f %%)\n",
                    c.surface.c_str(), c.quantity.c_str(), required.c_str(), achieved.c_str(),
                    c.met ? "met" : "NOT MET", c.margin, unit.c_str(), 100.0 * c.margin_rel);
    }
    out += line;
  }
  return out;
}

}  // namespace luxgrid::report
