#include "report/requirements.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "calc/json_reader.h"
#include "report/task_presets.h"
#include "util/error.h"

namespace luxgrid::report {

namespace {

using calc::JsonValue;

// In the order checks are listed.
constexpr const char* kQuantities[] = {"Em", "U0", "Emin", "Emax", "Ez", "Esc", "modelling", "UGR_L", "Ra"};
constexpr const char* kTaskKeysText =
    "Em, U0, Emin, Emax, Ez, Esc, UGR_L, Ra, modelling, preset, glare_observers, cylindrical or horizontal";

bool is_one_of(const std::string& key, std::initializer_list<const char*> keys) {
  for (const char* k : keys) {
    if (key == k) return true;
  }
  return false;
}

std::string citation(const TaskPreset& p) {
  return std::string(p.key) + ": " + p.edition + " " + p.table + ", ref. " + p.reference;
}

// The "quantity" of a raw surface entry (default planar).
std::string quantity_of(const nlohmann::json& entry) {
  return entry.contains("quantity") && entry["quantity"].is_string() ? entry["quantity"].get<std::string>() : "planar";
}

// A raw surface entry by name, or null.
const nlohmann::json* find_entry(const nlohmann::json& surfaces, const std::string& name) {
  for (const auto& s : surfaces) {
    if (s.is_object() && s.contains("name") && s["name"].is_string() && s["name"] == name) return &s;
  }
  return nullptr;
}

double parse_limit(const JsonValue& v, const std::string& key) {
  double limit = 0.0;
  if (key == "U0") {
    limit = v.as_number_in(0.0, 1.0);
  } else if (key == "Ra") {
    limit = v.as_number_in(0.0, 100.0);
  } else {
    limit = v.as_non_negative();
  }
  if (!(limit > 0.0)) v.fail("expected a positive number, got " + v.raw().dump());
  return limit;
}

// Em, U0, Emin, Emax of a wall, ceiling or floor object.
void parse_illuminance_limits(const JsonValue& obj, SurfaceRequirements& out) {
  if (!obj.is_object()) obj.fail("expected an object such as {\"Em\": 50, \"U0\": 0.1}, got " + calc::json_type_name(obj.raw()));
  for (const auto& [key, _] : obj.raw().items()) {
    const auto v = obj.at(key.c_str());
    if (!is_one_of(key, {"Em", "U0", "Emin", "Emax"})) v.fail("unknown quantity \"" + key + "\", expected Em, U0, Emin or Emax");
    out.limits[key] = parse_limit(v, key);
    out.from_preset.erase(key);
  }
}

std::vector<std::string> names_of(const JsonValue& v) {
  std::vector<std::string> out;
  if (v.is_string()) {
    out.push_back(v.as_string());
  } else if (v.is_array()) {
    for (const auto& item : v.items()) out.push_back(item.as_string());
    if (out.empty()) v.fail("expected a surface name or a list of them");
  } else {
    v.fail("expected a surface name or a list of them, got " + calc::json_type_name(v.raw()));
  }
  return out;
}

void parse_room_surfaces(const JsonValue& req, const std::string& name, Requirements& out) {
  SurfaceRequirements walls, ceiling, floor;
  walls.role = "wall";
  ceiling.role = "ceiling";
  floor.role = "floor";
  if (auto p = req.find("preset")) {
    const std::string key = p->as_string();
    if (key == kWallsAndCeilingsPreset) {
      const std::string cite = std::string(kWallsAndCeilingsPreset) + ": EN 12464-1:2021 clause 5.2.4";
      walls.limits = {{"Em", kMinWall_lx}, {"U0", kWallCeilingU0}};
      ceiling.limits = {{"Em", kMinCeiling_lx}, {"U0", kWallCeilingU0}};
      walls.from_preset = {{"Em", cite}, {"U0", cite}};
      ceiling.from_preset = walls.from_preset;
    } else if (const TaskPreset* row = find_task_preset(key)) {
      if (!row->Em_wall_lx || !row->Em_ceiling_lx) {
        p->fail("preset \"" + key + "\" gives no wall and ceiling illuminance; use \"" + kWallsAndCeilingsPreset +
                "\" or state \"walls\" and \"ceiling\"");
      }
      walls.limits = {{"Em", *row->Em_wall_lx}, {"U0", kWallCeilingU0}};
      ceiling.limits = {{"Em", *row->Em_ceiling_lx}, {"U0", kWallCeilingU0}};
      walls.from_preset = {{"Em", citation(*row)}, {"U0", citation(*row)}};
      ceiling.from_preset = walls.from_preset;
    } else {
      p->fail("unknown preset \"" + key + "\", expected " + kWallsAndCeilingsPreset + ", " + task_preset_keys());
    }
    walls.preset = ceiling.preset = key;
  }
  for (const auto& [key, _] : req.raw().items()) {
    const auto v = req.at(key.c_str());
    if (key == "preset") continue;
    if (key == "walls") parse_illuminance_limits(v, walls);
    else if (key == "ceiling") parse_illuminance_limits(v, ceiling);
    else if (key == "floor") parse_illuminance_limits(v, floor);
    else v.fail("unknown key \"" + key + "\" for room_surfaces requirements, expected preset, walls, ceiling or floor");
  }
  if (!walls.limits.empty()) out.walls[name] = walls;
  if (!ceiling.limits.empty()) out.surfaces[name + " ceiling"] = ceiling;
  if (!floor.limits.empty()) out.surfaces[name + " floor"] = floor;
}

void parse_task_area(const JsonValue& req, const nlohmann::json& entry, const nlohmann::json& surfaces,
                     const std::string& name, Requirements& out) {
  SurfaceRequirements r;
  const std::string quantity = quantity_of(entry);
  const bool cylindrical = quantity == "cylindrical";
  const bool horizontal = quantity == "planar" || quantity == "horizontal";
  for (const auto& [key, _] : req.raw().items()) {
    const auto v = req.at(key.c_str());
    if (is_one_of(key, {"Em", "U0", "Emin", "Emax", "Ez", "Esc", "UGR_L", "Ra"})) {
      r.limits[key] = parse_limit(v, key);
    } else if (key == "modelling") {
      const auto range = v.as_numbers(2);
      if (!(range[0] > 0.0 && range[0] < range[1])) v.fail("expected [low, high] with 0 < low < high, such as [0.3, 0.6]");
      r.modelling = std::make_pair(range[0], range[1]);
    } else if (key == "glare_observers") {
      r.glare_observers = names_of(v);
      for (const auto& n : r.glare_observers) {
        if (!find_entry(surfaces, n)) v.fail("no surface named \"" + n + "\"");
      }
    } else if (key == "cylindrical" || key == "horizontal") {
      const std::string target = v.as_string();
      const nlohmann::json* t = find_entry(surfaces, target);
      if (!t) v.fail("no surface named \"" + target + "\"");
      const std::string tq = quantity_of(*t);
      if (key == "cylindrical") {
        if (cylindrical) v.fail("surface \"" + name + "\" is cylindrical itself; \"cylindrical\" names another surface for a planar or horizontal task area");
        if (tq != "cylindrical") v.fail("surface \"" + target + "\" computes " + tq + " illuminance, not cylindrical");
        r.cylindrical = target;
      } else {
        if (!cylindrical) v.fail("\"horizontal\" pairs a cylindrical surface with a horizontal one for modelling; surface \"" + name + "\" computes " + quantity + " illuminance");
        if (tq != "planar" && tq != "horizontal") v.fail("surface \"" + target + "\" computes " + tq + " illuminance, not horizontal");
        r.horizontal = target;
      }
    } else if (key == "preset") {
      r.preset = v.as_string();
    } else {
      v.fail("unknown quantity \"" + key + "\", expected " + kTaskKeysText);
    }
  }
  // Each quantity needs a surface that computes it: say so at the key, not as a wrong number.
  auto need = [&](const char* key, bool ok, const std::string& how) {
    if (r.limits.count(key) || (std::string(key) == "modelling" && r.modelling)) {
      if (!ok) req.at(key).fail("surface \"" + name + "\" computes " + quantity + " illuminance, so it cannot give " + key + "; " + how);
    }
  };
  need("Ez", cylindrical || !r.cylindrical.empty(),
       "give it \"quantity\": \"cylindrical\", or name a cylindrical surface with \"cylindrical\": \"<surface>\"");
  need("Esc", quantity == "semi-cylindrical", "give a surface \"quantity\": \"semi-cylindrical\" and state Esc there");
  need("modelling", (cylindrical && !r.horizontal.empty()) || (horizontal && !r.cylindrical.empty()),
       "modelling is Ez / Eh point by point: on a cylindrical surface name its horizontal twin with \"horizontal\", "
       "on a horizontal one its cylindrical twin with \"cylindrical\"");
  if (!r.preset.empty()) {
    const auto v = req.at("preset");
    const TaskPreset* row = find_task_preset(r.preset);
    if (!row) v.fail("unknown preset \"" + r.preset + "\", expected " + task_preset_keys());
    if (!horizontal) v.fail("a task preset belongs on the task area, a planar or horizontal surface; surface \"" + name + "\" computes " + quantity + " illuminance");
    auto fill = [&](const char* key, std::optional<double> value) {
      if (!value || r.limits.count(key)) return;  // explicit keys override the preset
      r.limits[key] = *value;
      r.from_preset[key] = citation(*row);
    };
    fill("Em", row->Em_lx);
    fill("U0", row->U0);
    fill("UGR_L", row->UGR_L);
    fill("Ra", row->Ra);
    fill("Ez", row->Ez_lx);
  }
  out.surfaces[name] = r;
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
    throw InputError("requirements: modelling pairs \"" + a.name + "\" (" + std::to_string(a.points.size()) +
                     " points) with \"" + b.name + "\" (" + std::to_string(b.points.size()) +
                     " points); they must be the same grid, once cylindrical and once horizontal");
  }
  Achieved out;
  out.value = std::numeric_limits<double>::infinity();
  out.value_max = -std::numeric_limits<double>::infinity();
  size_t used = 0, dark = 0;
  for (size_t i = 0; i < a.points.size(); ++i) {
    if (glm::length(a.points[i] - b.points[i]) > kModellingPairTolerance_m) {
      throw InputError("requirements: modelling pairs \"" + a.name + "\" with \"" + b.name + "\", but their point " +
                       std::to_string(i) + " differs; they must be the same grid, once cylindrical and once horizontal");
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
  out.note = "Ez / Eh over " + std::to_string(used) + " points of \"" + a.name + "\" / \"" + b.name + "\"";
  if (dark) out.note += " (" + std::to_string(dark) + " without horizontal light left out)";
  return out;
}

Achieved achieved_value(const calc::Results& results, const calc::SurfaceResult& s, const SurfaceRequirements& r,
                        const std::string& q, const ComplianceInputs& inputs) {
  const auto& st = s.stats;
  if (q == "Em") return {true, st.Eavg, std::nullopt, ""};
  if (q == "U0") return {true, st.U0, std::nullopt, ""};
  if (q == "Emin") return {true, st.Emin, std::nullopt, ""};
  if (q == "Emax") return {true, st.Emax, std::nullopt, ""};
  if (q == "Esc") return {true, st.Eavg, std::nullopt, ""};
  if (q == "Ez") {
    if (s.grid.quantity == geometry::Quantity::cylindrical) return {true, st.Eavg, std::nullopt, ""};
    if (r.cylindrical.empty()) {
      return {false, 0.0, std::nullopt, "no cylindrical surface named (\"cylindrical\": \"<surface>\")"};
    }
    return {true, surface_named(results, r.cylindrical).stats.Eavg, std::nullopt, "Eavg of \"" + r.cylindrical + "\""};
  }
  if (q == "modelling") {
    if (s.grid.quantity == geometry::Quantity::cylindrical) return modelling_ratio(s, surface_named(results, r.horizontal));
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
        if (!is_observers(o)) return {false, 0.0, std::nullopt, "surface \"" + name + "\" gives no UGR (not an observers surface)"};
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
  if (!inputs.Ra) return {false, 0.0, std::nullopt, inputs.Ra_source.empty() ? "unknown" : inputs.Ra_source};
  return {true, *inputs.Ra, std::nullopt, inputs.Ra_source};
}

void check_surface(const calc::Results& results, const calc::SurfaceResult& s, const SurfaceRequirements& r,
                   const ComplianceInputs& inputs, std::vector<RequirementCheck>& checks) {
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

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

}  // namespace

std::string requirement_unit(const std::string& q) {
  return is_one_of(q, {"Em", "Emin", "Emax", "Ez", "Esc"}) ? " lx" : "";
}

Requirements parse_requirements(const nlohmann::json& project, const std::string& label) {
  Requirements out;
  if (!project.is_object() || !project.contains("surfaces") || !project["surfaces"].is_array()) return out;
  const nlohmann::json& raw_surfaces = project["surfaces"];
  const JsonValue surfaces(raw_surfaces, label, "/surfaces");
  for (const auto& s : surfaces.items()) {
    if (!s.is_object() || !s.has("requirements")) continue;
    const auto req = s.at("requirements");
    if (!req.is_object()) req.fail("expected an object such as {\"Em\": 500, \"U0\": 0.6}, got " + calc::json_type_name(req.raw()));
    const std::string name = s.has("name") && s.at("name").is_string() ? s.at("name").as_string() : "";
    if (name.empty()) s.at("name").fail("expected the surface's name");
    if (s.has("escape_route") || s.has("open_area")) {
      req.fail(
          "an escape_route or open_area surface takes no requirements: EN 1838's checks are made "
          "on it in "
          "the emergency scene (docs/compliance.md)");
    }
    if (s.has("room_surfaces")) {
      parse_room_surfaces(req, name, out);
    } else {
      parse_task_area(req, s.raw(), raw_surfaces, name, out);
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

std::vector<RequirementCheck> check_requirements(const calc::Results& results, const Requirements& req,
                                                 const ComplianceInputs& inputs) {
  std::vector<RequirementCheck> checks;
  for (const auto& [name, _] : req.surfaces) surface_named(results, name);
  for (const auto& [entry, _] : req.walls) {
    bool found = false;
    for (const auto& s : results.surfaces) found = found || s.grid.name.rfind(entry + " wall ", 0) == 0;
    if (!found) throw InputError("requirements: room_surfaces \"" + entry + "\" gave no wall grids");
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
                      {"limit", c.required_max ? "range" : c.upper_limit ? "max" : "min"},
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
        c.required_max ? fmt("%g", c.required) + " to " + fmt("%g", *c.required_max)
                       : std::string(c.upper_limit ? "<= " : ">= ") + fmt("%g", c.required) + unit;
    if (!c.calculated) {
      std::snprintf(line, sizeof line, "%-20s %-9s required %s  NOT CALCULATED (%s)\n", c.surface.c_str(),
                    c.quantity.c_str(), required.c_str(), c.note.c_str());
    } else {
      const std::string achieved = c.achieved_max ? fmt("%.3g", c.achieved) + " to " + fmt("%.3g", *c.achieved_max)
                                                  : fmt("%.4g", c.achieved) + unit;
      std::snprintf(line, sizeof line, "%-20s %-9s required %s  achieved %s  %s (%+.4g%s, %+.1f %%)\n",
                    c.surface.c_str(), c.quantity.c_str(), required.c_str(), achieved.c_str(),
                    c.met ? "met" : "NOT MET", c.margin, unit.c_str(), 100.0 * c.margin_rel);
    }
    out += line;
  }
  return out;
}

}  // namespace luxgrid::report
