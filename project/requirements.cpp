#include "project/requirements.h"

#include <algorithm>
#include <cmath>

#include "project/task_presets.h"
#include "util/error.h"

namespace luxgrid::project {

namespace {

// The keys of a task area's requirements, for messages.
constexpr const char* kTaskKeysText =
    "Em, U0, Emin, Emax, Ez, Esc, UGR_L, Ra, modelling, preset, glare_observers, cylindrical or "
    "horizontal";

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
  return entry.contains("quantity") && entry["quantity"].is_string()
             ? entry["quantity"].get<std::string>()
             : "planar";
}

// A raw surface entry by name, or null.
const nlohmann::json* find_entry(const nlohmann::json& surfaces, const std::string& name) {
  for (const auto& s : surfaces) {
    if (s.is_object() && s.contains("name") && s["name"].is_string() && s["name"] == name)
      return &s;
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
  if (!obj.is_object())
    obj.fail("expected an object such as {\"Em\": 50, \"U0\": 0.1}, got " +
             json_type_name(obj.raw()));
  for (const auto& [key, _] : obj.raw().items()) {
    const auto v = obj.at(key.c_str());
    if (!is_one_of(key, {"Em", "U0", "Emin", "Emax"}))
      v.fail("unknown quantity \"" + key + "\", expected Em, U0, Emin or Emax");
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
    v.fail("expected a surface name or a list of them, got " + json_type_name(v.raw()));
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
      const std::string cite =
          std::string(kWallsAndCeilingsPreset) + ": EN 12464-1:2021 clause 5.2.4";
      walls.limits = {{"Em", kMinWall_lx}, {"U0", kWallCeilingU0}};
      ceiling.limits = {{"Em", kMinCeiling_lx}, {"U0", kWallCeilingU0}};
      walls.from_preset = {{"Em", cite}, {"U0", cite}};
      ceiling.from_preset = walls.from_preset;
    } else if (const TaskPreset* row = find_task_preset(key)) {
      if (!row->Em_wall_lx || !row->Em_ceiling_lx) {
        p->fail("preset \"" + key + "\" gives no wall and ceiling illuminance; use \"" +
                kWallsAndCeilingsPreset + "\" or state \"walls\" and \"ceiling\"");
      }
      walls.limits = {{"Em", *row->Em_wall_lx}, {"U0", kWallCeilingU0}};
      ceiling.limits = {{"Em", *row->Em_ceiling_lx}, {"U0", kWallCeilingU0}};
      walls.from_preset = {{"Em", citation(*row)}, {"U0", citation(*row)}};
      ceiling.from_preset = walls.from_preset;
    } else {
      p->fail("unknown preset \"" + key + "\", expected " + kWallsAndCeilingsPreset + ", " +
              task_preset_keys());
    }
    walls.preset = ceiling.preset = key;
  }
  for (const auto& [key, _] : req.raw().items()) {
    const auto v = req.at(key.c_str());
    if (key == "preset") continue;
    if (key == "walls")
      parse_illuminance_limits(v, walls);
    else if (key == "ceiling")
      parse_illuminance_limits(v, ceiling);
    else if (key == "floor")
      parse_illuminance_limits(v, floor);
    else
      v.fail("unknown key \"" + key +
             "\" for room_surfaces requirements, expected preset, walls, ceiling or floor");
  }
  if (!walls.limits.empty()) out.walls[name] = walls;
  if (!ceiling.limits.empty()) out.surfaces[name + " ceiling"] = ceiling;
  if (!floor.limits.empty()) out.surfaces[name + " floor"] = floor;
}

void parse_task_area(const JsonValue& req, const nlohmann::json& entry,
                     const nlohmann::json& surfaces, const std::string& name, Requirements& out) {
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
      if (!(range[0] > 0.0 && range[0] < range[1]))
        v.fail("expected [low, high] with 0 < low < high, such as [0.3, 0.6]");
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
        if (cylindrical)
          v.fail("surface \"" + name +
                 "\" is cylindrical itself; \"cylindrical\" names another surface for a planar or "
                 "horizontal task area");
        if (tq != "cylindrical")
          v.fail("surface \"" + target + "\" computes " + tq + " illuminance, not cylindrical");
        r.cylindrical = target;
      } else {
        if (!cylindrical)
          v.fail(
              "\"horizontal\" pairs a cylindrical surface with a horizontal one for modelling; "
              "surface \"" +
              name + "\" computes " + quantity + " illuminance");
        if (tq != "planar" && tq != "horizontal")
          v.fail("surface \"" + target + "\" computes " + tq + " illuminance, not horizontal");
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
      if (!ok)
        req.at(key).fail("surface \"" + name + "\" computes " + quantity +
                         " illuminance, so it cannot give " + key + "; " + how);
    }
  };
  need("Ez", cylindrical || !r.cylindrical.empty(),
       "give it \"quantity\": \"cylindrical\", or name a cylindrical surface with \"cylindrical\": "
       "\"<surface>\"");
  need("Esc", quantity == "semi-cylindrical",
       "give a surface \"quantity\": \"semi-cylindrical\" and state Esc there");
  need("modelling",
       (cylindrical && !r.horizontal.empty()) || (horizontal && !r.cylindrical.empty()),
       "modelling is Ez / Eh point by point: on a cylindrical surface name its horizontal twin "
       "with \"horizontal\", "
       "on a horizontal one its cylindrical twin with \"cylindrical\"");
  if (!r.preset.empty()) {
    const auto v = req.at("preset");
    const TaskPreset* row = find_task_preset(r.preset);
    if (!row) v.fail("unknown preset \"" + r.preset + "\", expected " + task_preset_keys());
    if (!horizontal)
      v.fail("a task preset belongs on the task area, a planar or horizontal surface; surface \"" +
             name + "\" computes " + quantity + " illuminance");
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

}  // namespace

void parse_requirements(const JsonValue& req, const JsonValue& surface, const JsonValue& surfaces,
                        Requirements& out) {
  if (!req.is_object())
    req.fail("expected an object such as {\"Em\": 500, \"U0\": 0.6}, got " +
             json_type_name(req.raw()));
  const std::string name = surface.at("name").as_string();
  if (surface.has("escape_route") || surface.has("open_area")) {
    req.fail(
        "an escape_route or open_area surface takes no requirements: EN 1838's checks are made "
        "on it in the emergency scene (docs/compliance.md)");
  }
  if (surface.has("room_surfaces")) {
    parse_room_surfaces(req, name, out);
  } else {
    parse_task_area(req, surface.raw(), surfaces.raw(), name, out);
  }
}

Requirements parse_requirements(const nlohmann::json& project, const std::string& label) {
  Requirements out;
  if (!project.is_object() || !project.contains("surfaces") || !project["surfaces"].is_array())
    return out;
  const JsonDocument document(project, label);
  const JsonValue surfaces = document.root().at("surfaces");
  for (const auto& s : surfaces.items()) {
    if (auto req = s.find("requirements")) parse_requirements(*req, s, surfaces, out);
  }
  return out;
}

}  // namespace luxgrid::project
