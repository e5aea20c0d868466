#include "project/project_file.h"

#include <algorithm>
#include <set>

#include "calc/luminaire_tilt.h"
#include "calc/points_in_openings.h"
#include "geometry/prism_union.h"
#include "project/json_reader.h"
#include "project/project_limits.h"
#include "project/project_parts.h"
#include "project/requirements.h"
#include "project/safe_json.h"
#include "project/sanity_checks.h"
#include "util/error.h"
#include "util/sha256.h"

namespace luxgrid::project {

// The loader builds calc's types (Scene, Room, Luminaire, Settings) on every line.
using namespace calc;
using namespace parts;

Project parse_project(const nlohmann::json& doc, const std::string& label,
                      const std::filesystem::path& base_dir, const JsonPositions* positions) {
  const JsonDocument document(doc, label, positions);
  const JsonValue root = document.root();
  root.expect_object();
  const auto format = root.at("format");
  if (format.as_string() != kProjectFormat) {
    format.fail(std::string("expected \"") + kProjectFormat + "\", got \"" + format.as_string() +
                "\"");
  }
  Project project;
  Scene& scene = project.scene;
  scene.name = root.has("name") ? root.at("name").as_string() : "unnamed project";
  if (auto s = root.find("settings")) {
    scene.settings = parse_settings(*s);
    s->report_unqueried();
  }

  const FilePolicy files{base_dir, scene.settings.allow_files_outside_project};
  // A daylight project may have neither photometry nor luminaires.
  static const nlohmann::json kNoEntries = nlohmann::json::object();
  const bool daylight_only = root.has("daylight") && !root.has("photometry");
  const auto ph =
      daylight_only ? JsonValue(kNoEntries, document, "/photometry") : root.at("photometry");
  if (!ph.is_object())
    ph.fail("expected an object of named entries, got " + json_type_name(ph.raw()));
  check_count(ph, kMaxPhotometryEntries, "photometry entries");
  for (const auto& [key, _] : ph.raw().items()) {
    const auto entry = ph.at(key.c_str());
    auto p = parse_photometry_entry(entry, files);
    entry.report_unqueried();
    // The reader's warnings name the file; the place says which entry loaded it, once per entry.
    for (const auto& w : p.warnings) scene.warnings.push_back({entry.location(), w});
    scene.photometry.emplace(key, std::move(p));
  }
  const auto rooms = root.at("rooms");
  check_count(rooms, kMaxRooms, "rooms");
  size_t obstacles = 0;
  for (const auto& r : rooms.items()) {
    // Counted before any is built: each is CGAL geometry.
    if (auto o = r.find("obstacles"); o && o->is_array()) {
      obstacles += o->raw().size();
      if (obstacles > kMaxObstacles) {
        o->fail("the project would have " + std::to_string(obstacles) +
                " obstacles, more than the limit of " + std::to_string(kMaxObstacles));
      }
    }
    Room room = parse_room(r, scene.warnings);
    r.report_unqueried();
    for (const auto& other : scene.rooms) {
      if (other.name == room.name)
        r.at("name").fail("a room named \"" + room.name + "\" already exists");
      // Each room's reflected light is solved apart, so volume two rooms share would be lit by
      // both (and a room inside a lit room would receive the outer room's reflected light).
      // Rooms may touch: a shared wall, a floor that is the ceiling of the room below.
      if (geometry::prism_contact(room.outline, room.floor_z, room.floor_z + room.height,
                                  other.outline, other.floor_z, other.floor_z + other.height) ==
          geometry::PrismContact::overlap) {
        r.fail("rooms \"" + other.name + "\" and \"" + room.name +
               "\" overlap (share volume); each room's light is calculated apart, so the shared "
               "volume would be lit twice: give them outlines or heights that do not overlap (a "
               "room inside another: an obstacle of the outer room, or a room of its own beside "
               "it)");
      }
    }
    scene.rooms.push_back(std::move(room));
  }
  if (auto o = root.find("openings")) parse_openings(*o, scene);
  if (auto d = root.find("daylight")) {
    scene.daylight = parse_daylight(*d);
    if (auto o = d->find("obstructions"))
      scene.daylight->obstructions = parse_obstructions(*o, scene);
    d->report_unqueried();
  }
  if (scene.settings.scene == LightingScene::daylight && !scene.daylight)
    root.at("settings")
        .at("scene")
        .fail("the daylight scene needs a \"daylight\" object (sky, sun, diffuse illuminance)");
  // A daylight project may have no luminaires.
  const bool luminaires_optional = scene.daylight.has_value() && !root.has("luminaires");
  size_t index = 0;
  for (const auto& l :
       luminaires_optional ? std::vector<JsonValue>{} : root.at("luminaires").items()) {
    const std::size_t first = scene.luminaires.size();
    parse_luminaire(l, index++, scene, scene.luminaires);
    l.report_unqueried();
    warn_about_luminaires(l, first, scene);
  }
  const auto surfaces = root.at("surfaces");
  check_count(surfaces, kMaxSurfaces, "surfaces");
  // Every surface is charged its points from its definition before any grid is built, so a
  // project refused for its total builds none (kMaxTotalGridPoints: 8 million points, 640 MB).
  GridBudget count(scene.luminaires.size(), GridBudget::Mode::count_only);
  for (const auto& s : surfaces.items()) (void)parse_surface(s, scene, count);
  GridBudget budget(scene.luminaires.size());
  OutputNames outputs;
  std::set<std::string> names;
  for (const auto& s : surfaces.items()) {
    auto grids = parse_surface(s, scene, budget);
    check_observers_inputs(s, scene);
    if (s.has("observers") && !grids.empty()) check_observer_places(s, grids.front(), scene);
    if (auto r = s.find("requirements")) parse_requirements(*r, s, surfaces, project.requirements);
    record_emergency_surfaces(s, grids, scene.emergency_surfaces);
    s.report_unqueried();
    for (auto& grid : grids) {
      calc::leave_out_points_in_openings(scene, grid);
      if (grid.points_in_openings > 0 &&
          std::none_of(grid.active.begin(), grid.active.end(), [](bool a) { return a; }))
        scene.warnings.push_back({s.location(), "surface \"" + grid.name +
                                                    "\": every point lies in an opening (no "
                                                    "surface there): no results"});
      const auto name_v = s.at("name");
      if (!names.insert(grid.name).second)
        name_v.fail("a surface named \"" + grid.name + "\" already exists");
      if (names.size() > kMaxSurfaceGrids) {
        name_v.fail("the surfaces would give " + std::to_string(names.size()) +
                    " grids, more than the limit of " + std::to_string(kMaxSurfaceGrids));
      }
      check_name_length(name_v, grid.name);  // room_surfaces: "<name> wall 12"
      outputs.claim(name_v, grid.name);
      scene.surfaces.push_back(std::move(grid));
    }
  }
  if (scene.surfaces.empty()) surfaces.fail("expected at least one calculation surface");
  if (scene.daylight && scene.daylight->en17037)
    resolve_en17037_planes(root.at("daylight").at("en17037"), surfaces, scene);
  // IES TILT tables hold for the lamp as measured; a luminaire turned in the scene gets its
  // file's factor at its actual tilt, once, here, so every later stage sees the scaled output.
  apply_tilt_factors(scene);
  // Legal input that is usually a mistake (millimetres, kilolumens, radians, ...): warnings.
  add_sanity_warnings(scene, root);
  root.report_unqueried();
  return project;
}

Project parse_project_text(std::string_view text, const std::string& label,
                           const std::filesystem::path& base_dir) {
  JsonPositions positions;
  const nlohmann::json doc = parse_json_text(text, label, &positions);
  return parse_project(doc, label, base_dir, &positions);
}

Project load_project(const std::filesystem::path& file) {
  // JSON-level messages name the file as given; the scene's name only its file name. The bytes
  // are read once: the hash in results.json is of exactly what was parsed.
  const std::string text = read_bounded_file(file);
  JsonPositions positions;
  const nlohmann::json doc = parse_json_text(text, file.string(), &positions);
  Project project = parse_project(doc, file.filename().string(), file.parent_path(), &positions);
  project.scene.project_file = file;
  project.scene.project_sha256 = sha256_hex(text);
  return project;
}

}  // namespace luxgrid::project
