#include "report/report_input_json.h"

#include <optional>

#include "calc/opening_placement.h"
#include "project/safe_json.h"
#include "report/en17037_checks.h"
#include "report/json_fields.h"
#include "report/plan_json.h"
#include "report/results_json.h"
#include "util/error.h"

namespace luxgrid::report {

namespace {
using nlohmann::json;

json vec2(const Vec2& v) { return json::array({v.x, v.y}); }
Vec2 read_vec2(const json& j) { return {j.at(0).get<double>(), j.at(1).get<double>()}; }
Vec3 read_vec3(const json& j) {
  return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}
json polygon(const std::vector<Vec2>& p) {
  json out = json::array();
  for (const Vec2& v : p) out.push_back(vec2(v));
  return out;
}
std::vector<Vec2> read_polygon(const json& j) {
  std::vector<Vec2> out;
  for (const json& v : j) out.push_back(read_vec2(v));
  return out;
}
// An optional number is written only when it has a value: results.json holds no null
// (docs/reliability.md); a key left out reads back as no value.
void put_optional(json& j, const char* key, const std::optional<double>& v) {
  if (v) j[key] = *v;
}
// A value results.json documents as null where it does not exist (an observer's UGR).
std::optional<double> read_nullable(const json& j) {
  if (j.is_null()) return std::nullopt;
  return j.get<double>();
}
std::optional<double> read_optional(const json& j, const char* key) {
  const auto it = j.find(key);
  if (it == j.end()) return std::nullopt;
  return it->get<double>();
}

const char* shape_name(photometry::LuminousOpening::Shape s) {
  using Shape = photometry::LuminousOpening::Shape;
  return s == Shape::rectangle ? "rectangle" : s == Shape::disk ? "disk" : "point";
}
photometry::LuminousOpening::Shape read_shape(const json& j) {
  using Shape = photometry::LuminousOpening::Shape;
  const std::string s = j.get<std::string>();
  if (s == "rectangle") return Shape::rectangle;
  if (s == "disk") return Shape::disk;
  if (s == "point") return Shape::point;
  throw json::other_error::create(501, "unknown opening shape \"" + s + "\"", &j);
}

json room_json(const calc::Room& r) {
  json obstacles = json::array();
  for (const auto& o : r.obstacles)
    obstacles.push_back({{"name", o.name},
                         {"footprint", polygon(o.footprint)},
                         {"z0", o.z0},
                         {"z1", o.z1},
                         {"reflectance", o.reflectance}});
  return {{"name", r.name},
          {"outline", polygon(r.outline)},
          {"floor_z", r.floor_z},
          {"height", r.height},
          {"reflectance",
           {{"floor", r.reflectance.floor},
            {"walls", r.reflectance.walls},
            {"ceiling", r.reflectance.ceiling}}},
          {"obstacles", std::move(obstacles)}};
}
calc::Room read_room(const json& j) {
  calc::Room r;
  j.at("name").get_to(r.name);
  r.outline = read_polygon(j.at("outline"));
  read_fields(j, "floor_z", r.floor_z, "height", r.height);
  const json& rho = j.at("reflectance");
  read_fields(rho, "floor", r.reflectance.floor, "walls", r.reflectance.walls, "ceiling",
              r.reflectance.ceiling);
  for (const json& o : j.at("obstacles")) {
    geometry::Obstacle ob;
    o.at("name").get_to(ob.name);
    ob.footprint = read_polygon(o.at("footprint"));
    read_fields(o, "z0", ob.z0, "z1", ob.z1, "reflectance", ob.reflectance);
    r.obstacles.push_back(std::move(ob));
  }
  return r;
}

// A daylight opening as the project file gives it (docs/project-format.md), its room by name; the
// face it lies in is found again when it is read back, as the project loader found it.
json daylight_opening_json(const calc::DaylightOpening& o, const calc::Scene& scene) {
  json polygon = json::array();
  for (const Vec3& c : o.polygon) polygon.push_back(vec3_json(c));
  json j = {{"name", o.name},
            {"room", scene.rooms.at(o.room).name},
            {"polygon", std::move(polygon)},
            {"frame_factor", o.frame_factor},
            {"maintenance_factor", o.maintenance_factor}};
  if (o.glazing_transmittance) j["glazing"] = {{"transmittance", *o.glazing_transmittance}};
  return j;
}
calc::DaylightOpening read_daylight_opening(const json& j, const calc::Scene& scene) {
  calc::DaylightOpening o;
  j.at("name").get_to(o.name);
  const std::string room = j.at("room").get<std::string>();
  o.room = scene.rooms.size();
  for (std::size_t r = 0; r < scene.rooms.size(); ++r)
    if (scene.rooms[r].name == room) o.room = r;
  if (o.room == scene.rooms.size())
    throw json::other_error::create(501, "no room \"" + room + "\"", &j.at("room"));
  for (const json& c : j.at("polygon")) o.polygon.push_back(read_vec3(c));
  const calc::OpeningPlacement placed = calc::place_opening(scene.rooms[o.room], o.polygon);
  if (o.polygon.size() < 3 || !placed.found)
    throw json::other_error::create(501, "the opening lies in no face of its room", &j);
  o.face = placed.face, o.inward_normal = placed.inward_normal;
  read_fields(j, "frame_factor", o.frame_factor, "maintenance_factor", o.maintenance_factor);
  if (const auto it = j.find("glazing"); it != j.end())
    o.glazing_transmittance = it->at("transmittance").get<double>();
  return o;
}

// The site of a daylight scene (its north angle; where and when, when the sun was computed from
// it), which the plan's daylight part does not hold.
json daylight_site_json(const calc::DaylightInputs& d) {
  const daylight::Site& s = d.site;
  json j = {{"north_angle_deg", s.north_angle_deg}, {"sun_from_site", d.sun_from_site}};
  if (d.sun_from_site) {
    const daylight::LocalTime& t = d.local_time;
    j["latitude_deg"] = s.latitude_deg, j["longitude_deg"] = s.longitude_deg;
    j["timezone_h"] = s.timezone_h, j["elevation_m"] = s.elevation_m;
    j["local_time"] = {t.year, t.month, t.day, t.hour, t.minute, t.second};
  }
  return j;
}
calc::DaylightInputs read_daylight_site(const json& j) {
  calc::DaylightInputs d;
  read_fields(j, "north_angle_deg", d.site.north_angle_deg, "sun_from_site", d.sun_from_site);
  if (d.sun_from_site) {
    read_fields(j, "latitude_deg", d.site.latitude_deg, "longitude_deg", d.site.longitude_deg,
                "timezone_h", d.site.timezone_h, "elevation_m", d.site.elevation_m);
    const json& t = j.at("local_time");
    daylight::LocalTime& l = d.local_time;
    t.at(0).get_to(l.year), t.at(1).get_to(l.month), t.at(2).get_to(l.day);
    t.at(3).get_to(l.hour), t.at(4).get_to(l.minute), t.at(5).get_to(l.second);
  }
  return d;
}

// The rotation by its columns (the luminaire frame's axes in the world).
json luminaire_json(const calc::Luminaire& l) {
  const auto& m = l.pose.rotation;
  return {{"label", l.label},
          {"photometry", l.photometry},
          {"position", vec3_json(l.pose.position)},
          {"rotation", json::array({vec3_json(m[0]), vec3_json(m[1]), vec3_json(m[2])})},
          {"opening",
           {{"shape", shape_name(l.opening.shape)},
            {"length", l.opening.length},
            {"width", l.opening.width},
            {"height", l.opening.height},
            {"description", l.opening.description}}}};
}
calc::Luminaire read_luminaire(const json& j) {
  calc::Luminaire l;
  read_fields(j, "label", l.label, "photometry", l.photometry);
  l.pose.position = read_vec3(j.at("position"));
  for (int c = 0; c < 3; ++c) l.pose.rotation[c] = read_vec3(j.at("rotation").at(c));
  const json& o = j.at("opening");
  l.opening.shape = read_shape(o.at("shape"));
  read_fields(o, "length", l.opening.length, "width", l.opening.width, "height", l.opening.height,
              "description", l.opening.description);
  return l;
}

json type_json(const LuminaireType& t) {
  json j = {{"key", t.key},         {"name", t.name},     {"manufacturer", t.manufacturer},
            {"article", t.article}, {"format", t.format}, {"file", t.file},
            {"count", t.count}};
  put_optional(j, "flux_lm", t.flux_lm);
  put_optional(j, "power_W", t.power_W);
  put_optional(j, "lor", t.lor);
  put_optional(j, "ugr_crosswise", t.ugr_crosswise);
  put_optional(j, "ugr_endwise", t.ugr_endwise);
  if (t.polar)
    j["polar"] =
        json{{"step_deg", kPolarStepDeg}, {"c0_cd", t.polar->c0_cd}, {"c90_cd", t.polar->c90_cd}};
  if (t.solid)
    j["solid"] = json{{"c_step_deg", kSolidCStepDeg},
                      {"gamma_step_deg", kSolidGammaStepDeg},
                      {"cd", t.solid->cd}};
  return j;
}
LuminaireType read_type(const json& j) {
  LuminaireType t;
  read_fields(j, "key", t.key, "name", t.name, "manufacturer", t.manufacturer, "article", t.article,
              "format", t.format, "file", t.file, "count", t.count);
  t.flux_lm = read_optional(j, "flux_lm");
  t.power_W = read_optional(j, "power_W");
  t.lor = read_optional(j, "lor");
  t.ugr_crosswise = read_optional(j, "ugr_crosswise");
  t.ugr_endwise = read_optional(j, "ugr_endwise");
  if (const auto it = j.find("polar"); it != j.end()) {
    const json& p = *it;
    PolarCurves c;
    read_fields(p, "c0_cd", c.c0_cd, "c90_cd", c.c90_cd);
    t.polar = std::move(c);
  }
  if (const auto it = j.find("solid"); it != j.end()) {
    PhotometricSolid solid;
    it->at("cd").get_to(solid.cd);
    if (solid.cd.size() != static_cast<std::size_t>(kSolidCPlanes * kSolidGammas))
      throw json::other_error::create(501, "the solid's sample count is not 36 x 37", &*it);
    t.solid = std::move(solid);
  }
  return t;
}

json check_json(const RequirementCheck& c) {
  json j = {{"surface", c.surface},
            {"role", c.role},
            {"quantity", c.quantity},
            {"required", c.required},
            {"achieved", c.achieved},
            {"upper_limit", c.upper_limit},
            {"calculated", c.calculated},
            {"met", c.met},
            {"margin", c.margin},
            {"margin_rel", c.margin_rel},
            {"source", c.source},
            {"fixed_by_standard", c.fixed_by_standard},
            {"note", c.note}};
  put_optional(j, "required_max", c.required_max);
  put_optional(j, "achieved_max", c.achieved_max);
  return j;
}
RequirementCheck read_check(const json& j) {
  RequirementCheck c;
  read_fields(j, "surface", c.surface, "role", c.role, "quantity", c.quantity, "required",
              c.required);
  c.required_max = read_optional(j, "required_max");
  j.at("achieved").get_to(c.achieved);
  c.achieved_max = read_optional(j, "achieved_max");
  read_fields(j, "upper_limit", c.upper_limit, "calculated", c.calculated, "met", c.met, "margin",
              c.margin, "margin_rel", c.margin_rel, "source", c.source, "fixed_by_standard",
              c.fixed_by_standard, "note", c.note);
  return c;
}

// The frame and outline of a surface, which results.json's surface object does not hold.
json surface_frame_json(const geometry::SurfaceGrid& g) {
  json region = json::array();
  for (const auto& p : g.region) region.push_back(polygon(p));
  return {{"origin", vec3_json(g.origin)},
          {"u_dir", vec3_json(g.u_dir)},
          {"v_dir", vec3_json(g.v_dir)},
          {"size_u", g.size_u},
          {"size_v", g.size_v},
          {"observer", g.observer},
          {"region", std::move(region)}};
}

geometry::SurfaceGrid::Kind read_kind(const json& j) {
  using Kind = geometry::SurfaceGrid::Kind;
  const std::string s = j.get<std::string>();
  for (Kind k : {Kind::grid, Kind::points, Kind::observers})
    if (s == geometry::to_string(k)) return k;
  throw json::other_error::create(501, "unknown surface kind \"" + s + "\"", &j);
}
geometry::Quantity read_quantity(const json& j) {
  using Q = geometry::Quantity;
  const std::string s = j.get<std::string>();
  for (Q q : {Q::planar, Q::horizontal, Q::vertical, Q::cylindrical, Q::semi_cylindrical})
    if (s == geometry::to_string(q)) return q;
  throw json::other_error::create(501, "unknown quantity \"" + s + "\"", &j);
}

std::vector<calc::glare::ObserverResult> read_observers(const json& j) {
  std::vector<calc::glare::ObserverResult> out;
  for (const json& o : j) {
    calc::glare::ObserverResult r;
    r.at = read_vec3(o.at("at"));
    for (const json& v : o.at("views")) {
      calc::glare::ViewResult view;
      view.direction = read_vec3(v.at("direction"));
      view.UGR = read_nullable(v.at("UGR"));
      read_fields(v, "Lb", view.Lb_cd_m2, "E_indirect", view.E_indirect_lx);
      for (const json& t : v.at("terms")) {
        calc::glare::ViewTerm term;
        read_fields(t, "luminaire", term.luminaire, "L", term.term.L_cd_m2, "omega",
                    term.term.omega_sr, "p", term.term.p);
        view.terms.push_back(std::move(term));
      }
      r.views.push_back(std::move(view));
    }
    out.push_back(std::move(r));
  }
  return out;
}

calc::SurfaceResult read_surface(const json& s, const json& frame) {
  calc::SurfaceResult r;
  geometry::SurfaceGrid& g = r.grid;
  s.at("name").get_to(g.name);
  g.kind = read_kind(s.at("kind"));
  s.at("size").at(0).get_to(g.nu);
  s.at("size").at(1).get_to(g.nv);
  if (g.kind == geometry::SurfaceGrid::Kind::grid) {
    s.at("spacing").at(0).get_to(g.spacing_u);
    s.at("spacing").at(1).get_to(g.spacing_v);
  }
  g.quantity = read_quantity(s.at("quantity"));
  read_fields(s, "points_outside", g.points_outside, "points_in_obstacles", g.points_in_obstacles);
  if (s.contains("points_in_openings")) s.at("points_in_openings").get_to(g.points_in_openings);
  for (const json& p : s.at("points")) g.points.push_back(read_vec3(p));
  for (const json& n : s.at("normals")) g.normals.push_back(read_vec3(n));
  for (const json& a : s.at("active")) g.active.push_back(a.get<bool>());
  g.origin = read_vec3(frame.at("origin"));
  g.u_dir = read_vec3(frame.at("u_dir"));
  g.v_dir = read_vec3(frame.at("v_dir"));
  read_fields(frame, "size_u", g.size_u, "size_v", g.size_v, "observer", g.observer);
  for (const json& p : frame.at("region")) g.region.push_back(read_polygon(p));
  read_fields(s, "E", r.E, "E_direct", r.E_direct, "E_indirect", r.E_indirect);
  const size_t n = g.points.size();
  if (g.normals.size() != n || g.active.size() != n || r.E.size() != n || r.E_direct.size() != n ||
      r.E_indirect.size() != n || n != static_cast<size_t>(g.nu) * static_cast<size_t>(g.nv))
    throw json::other_error::create(
        501, "the per-point arrays differ in length from each other or from size", &s);
  if (s.contains("DF")) {
    read_fields(s, "DF", r.DF, "SC", r.SC, "ERC", r.ERC, "IRC", r.IRC);
    if (r.DF.size() != n || r.SC.size() != n || r.ERC.size() != n || r.IRC.size() != n)
      throw json::other_error::create(501, "the daylight arrays differ in length from points", &s);
  }
  if (s.contains("E_sun_direct")) {
    read_fields(s, "E_sun_direct", r.E_sun_direct, "E_sun_reflected", r.E_sun_reflected);
    if (r.E_sun_direct.size() != n || r.E_sun_reflected.size() != n)
      throw json::other_error::create(501, "the sun's arrays differ in length from points", &s);
  }
  const json& st = s.at("stats");
  // A statistic results.json wrote as null (not finite) is refused by the type check.
  read_fields(st, "Emin", r.stats.Emin, "Eavg", r.stats.Eavg, "Emax", r.stats.Emax, "U0",
              r.stats.U0, "Ud", r.stats.Ud);
  if (g.kind == geometry::SurfaceGrid::Kind::observers) {
    r.UGR_max = read_nullable(s.at("UGR_max"));
    r.observers = read_observers(s.at("observers"));
  }
  return r;
}

// nlohmann::json's message with JSON_DIAGNOSTICS names the value's place as "(/a/0/b) " after
// the exception's id: that is the pointer, the rest the message.
InputError located(const nlohmann::json::exception& e, const std::string& file) {
  std::string what = e.what();
  std::string pointer = "/";
  const size_t id_end = what.find("] ");
  if (id_end != std::string::npos) what = what.substr(id_end + 2);
  if (what.rfind("(", 0) == 0) {
    const size_t close = what.find(") ");
    if (close != std::string::npos) {
      pointer = what.substr(1, close - 1);
      what = what.substr(close + 2);
    }
  }
  return InputError(SourceLocation(file, 0, 0, pointer), what);
}

}  // namespace

json report_input_to_json(const calc::Scene& scene, const calc::Results& results,
                          const std::vector<LuminaireType>& types,
                          const std::vector<RequirementCheck>& checks) {
  json j;
  j["project_file"] = scene.project_file.filename().string();
  const auto& parts = scene.settings.maintenance_parts;
  if (parts)
    j["maintenance_parts"] = json{
        {"LLMF", parts->LLMF}, {"LSF", parts->LSF}, {"LMF", parts->LMF}, {"RSMF", parts->RSMF}};
  j["rooms"] = json::array();
  for (const auto& r : scene.rooms) j["rooms"].push_back(room_json(r));
  j["luminaires"] = json::array();
  for (const auto& l : scene.luminaires) j["luminaires"].push_back(luminaire_json(l));
  // Only when there are openings: results.json stays as it was for a project without.
  if (!scene.openings.empty()) {
    j["openings"] = json::array();
    for (const auto& o : scene.openings) j["openings"].push_back(daylight_opening_json(o, scene));
    if (scene.daylight) j["daylight_site"] = daylight_site_json(*scene.daylight);
  }
  j["surfaces"] = json::array();
  for (const auto& s : results.surfaces) j["surfaces"].push_back(surface_frame_json(s.grid));
  j["luminaire_types"] = json::array();
  for (const auto& t : types) j["luminaire_types"].push_back(type_json(t));
  j["checks"] = json::array();
  for (const auto& c : checks) j["checks"].push_back(check_json(c));
  return j;
}

ResultsDocument read_results_document(const std::string& text, const std::string& file) {
  // The checked parse of projects (project/safe_json.h): no repeated keys, bounded nesting.
  const json doc = project::parse_json_text(text, file);
  if (!doc.is_object() || !doc.contains("format") || doc["format"] != kResultsFormat)
    throw InputError(
        SourceLocation(file, 0, 0, "/format"),
        std::string("not a luxgrid results file of format \"") + kResultsFormat + "\"");
  if (!doc.contains("report_input"))
    throw InputError(SourceLocation(file, 0, 0, "/report_input"),
                     "missing: written by a luxgrid that did not keep what the report needs; "
                     "calculate the project again");
  ResultsDocument out;
  try {
    calc::Results& r = out.results;
    read_fields(doc, "project", r.project, "luxgrid_version", out.version);
    const auto quality = calc::quality_from_string(doc.at("quality").get<std::string>());
    if (!quality) throw json::other_error::create(501, "unknown quality", &doc.at("quality"));
    r.quality = *quality;
    const std::string scene = doc.at("scene").get<std::string>();
    if (scene != "normal" && scene != "emergency" && scene != "daylight")
      throw json::other_error::create(501, "unknown scene \"" + scene + "\"", &doc.at("scene"));
    r.scene = scene == "emergency"  ? calc::LightingScene::emergency
              : scene == "daylight" ? calc::LightingScene::daylight
                                    : calc::LightingScene::normal;
    doc.at("maintenance_factor").get_to(r.maintenance_factor);
    r.plan = plan_from_json(doc.at("plan"));
    const json& in = doc.at("report_input");
    const json& surfaces = doc.at("surfaces");
    const json& frames = in.at("surfaces");
    if (surfaces.size() != frames.size())
      throw json::other_error::create(501, "one frame per surface expected", &frames);
    for (size_t k = 0; k < surfaces.size(); ++k)
      r.surfaces.push_back(read_surface(surfaces.at(k), frames.at(k)));

    calc::Scene& s = out.scene;
    s.name = r.project;
    s.project_file = in.at("project_file").get<std::string>();
    s.settings.quality = r.quality;
    s.settings.scene = r.scene;
    s.settings.maintenance_factor = r.maintenance_factor;
    if (const auto it = in.find("maintenance_parts"); it != in.end()) {
      const json& p = *it;
      calc::MaintenanceFactors m;
      read_fields(p, "LLMF", m.LLMF, "LSF", m.LSF, "LMF", m.LMF, "RSMF", m.RSMF);
      s.settings.maintenance_parts = m;
    }
    for (const json& room : in.at("rooms")) s.rooms.push_back(read_room(room));
    for (const json& l : in.at("luminaires")) s.luminaires.push_back(read_luminaire(l));
    if (const auto it = in.find("openings"); it != in.end())
      for (const json& o : *it) s.openings.push_back(read_daylight_opening(o, s));
    if (const auto it = in.find("daylight_site"); it != in.end())
      s.daylight = read_daylight_site(*it);
    for (const auto& sr : r.surfaces) s.surfaces.push_back(sr.grid);
    for (const json& t : in.at("luminaire_types")) out.types.push_back(read_type(t));
    for (const json& c : in.at("checks")) out.checks.push_back(read_check(c));
    if (const auto it = doc.find("en17037"); it != doc.end()) out.en17037 = en17037_from_json(*it);
  } catch (const json::exception& e) {
    throw located(e, file);
  }
  return out;
}

}  // namespace luxgrid::report
