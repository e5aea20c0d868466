#include "calc/project_file.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "calc/json_reader.h"
#include "calc/luminaire_tilt.h"
#include "calc/scaled_distribution.h"
#include "calc/visibility.h"
#include "geometry/workplane.h"
#include "photometry/builtin.h"
#include "util/error.h"

namespace luxgrid::calc {

namespace {

// Grids larger than this are refused before any memory is spent on them: 4 million points is
// ~200 MB of points, normals and results, far beyond any lighting grid (a 100 x 100 m hall at
// 0.1 m is 1 M points).
constexpr double kMaxGridPoints = 4e6;

Settings parse_settings(const JsonValue& s) {
  s.expect_object({"quality", "near_field", "near_field_model", "indirect", "bounces",
                   "maintenance_factor"});
  Settings out;
  if (auto q = s.find("quality")) {
    const auto parsed = quality_from_string(q->as_string());
    if (!parsed) q->fail("expected \"draft\", \"standard\", \"high\" or \"reference\", got \"" +
                         q->as_string() + "\"");
    out.quality = *parsed;
  }
  if (auto n = s.find("near_field")) {
    const std::string v = n->as_string();
    if (v == "auto") out.near_field = NearFieldMode::automatic;
    else if (v == "always") out.near_field = NearFieldMode::always;
    else if (v == "never") out.near_field = NearFieldMode::never;
    else n->fail("expected \"auto\", \"always\" or \"never\", got \"" + v + "\"");
  }
  if (auto m = s.find("near_field_model")) out.near_field_model = m->as_string();
  if (auto i = s.find("indirect")) {
    const std::string v = i->as_string();
    if (v == "auto") out.indirect = IndirectMode::automatic;
    else if (v == "off") out.indirect = IndirectMode::off;
    else if (v == "on") out.indirect = IndirectMode::on;
    else i->fail("expected \"auto\", \"off\" or \"on\", got \"" + v + "\"");
  }
  if (auto b = s.find("bounces")) {
    if (b->is_string()) {
      if (b->as_string() != "auto") b->fail("expected \"auto\" or a whole number >= 1");
      out.bounces = 0;
    } else {
      out.bounces = b->as_int();
      if (out.bounces < 1) b->fail("expected \"auto\" or a whole number >= 1, got " + b->raw().dump());
    }
  }
  if (auto m = s.find("maintenance_factor")) {
    out.maintenance_factor = m->as_number_in(0.0, 1.0);
    if (out.maintenance_factor == 0.0) m->fail("expected a number in (0, 1], got 0");
  }
  return out;
}

photometry::Photometry parse_builtin(const JsonValue& e) {
  e.expect_object({"builtin", "intensity_cd"});
  const auto kind = e.at("builtin");
  const double i0 = e.at("intensity_cd").as_non_negative();
  photometry::Photometry p;
  p.format = "builtin";
  const std::string name = kind.as_string();
  if (name == "isotropic") {
    p.distribution = std::make_shared<photometry::IsotropicDistribution>(i0);
  } else if (name == "lambertian") {
    p.distribution = std::make_shared<photometry::LambertianDistribution>(i0);
  } else {
    kind.fail("expected \"isotropic\" or \"lambertian\", got \"" + name + "\"");
  }
  p.source = "builtin:" + name;
  return p;
}

photometry::Photometry load_file_entry(const JsonValue& where, const std::string& relative,
                                       const std::filesystem::path& base_dir) {
  const std::filesystem::path path = base_dir / relative;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    where.fail("photometry file not found: " + path.string());
  }
  auto p = photometry::load_photometry_file(path);
  p.source = relative;
  return p;
}

photometry::Photometry parse_photometry_entry(const JsonValue& e,
                                              const std::filesystem::path& base_dir) {
  if (e.is_string()) return load_file_entry(e, e.as_string(), base_dir);
  if (!e.is_object()) e.fail("expected a file path or an object, got " + json_type_name(e.raw()));
  if (e.has("builtin")) return parse_builtin(e);
  e.expect_object({"file", "flux_lm", "multiplier"});
  const auto file = e.at("file");
  auto p = load_file_entry(file, file.as_string(), base_dir);
  if (auto m = e.find("multiplier")) {
    p.distribution = std::make_shared<ScaledDistribution>(p.distribution, m->as_positive());
  }
  if (auto f = e.find("flux_lm")) {
    const double target = f->as_positive();
    const double have = luminous_flux(*p.distribution);
    if (!(have > 0.0)) f->fail("cannot rescale to flux_lm: the distribution emits no light");
    p.distribution = std::make_shared<ScaledDistribution>(p.distribution, target / have);
  }
  return p;
}

photometry::LuminousOpening parse_emitter(const JsonValue& e) {
  e.expect_object({"shape", "size", "diameter"});
  const auto shape = e.at("shape");
  const std::string s = shape.as_string();
  photometry::LuminousOpening o;
  if (s == "rectangle") {
    if (e.has("diameter")) e.at("diameter").fail("a rectangle takes \"size\", not \"diameter\"");
    const auto size = e.at("size");
    const auto v = size.as_numbers(2);
    if (!(v[0] > 0.0 && v[1] > 0.0)) size.fail("expected two positive sizes in metres");
    o.shape = photometry::LuminousOpening::Shape::rectangle;
    o.length = v[0];
    o.width = v[1];
  } else if (s == "disk") {
    if (e.has("size")) e.at("size").fail("a disk takes \"diameter\", not \"size\"");
    o.shape = photometry::LuminousOpening::Shape::disk;
    o.length = o.width = e.at("diameter").as_positive();
  } else if (s == "point") {
    if (e.has("size") || e.has("diameter")) e.fail("a point emitter has no size");
    o.shape = photometry::LuminousOpening::Shape::point;
  } else {
    shape.fail("expected \"rectangle\", \"disk\" or \"point\", got \"" + s + "\"");
  }
  return o;
}

// Geometry checks throw InputError("room \"L\": ..."); re-throw them at the JSON value they
// concern, so the message names both the place in the file and the object.
template <class F>
auto at_place(const JsonValue& where, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const InputError& e) {
    where.fail(e.what());
  }
}

geometry::Obstacle parse_obstacle(const JsonValue& o, size_t index, const Room& room,
                                  std::vector<std::string>& warnings) {
  o.expect_object({"name", "box", "prism", "reflectance"});
  const std::string name =
      o.has("name") ? o.at("name").as_string() : "obstacle " + std::to_string(index);
  // Furniture and columns: mid-grey unless given, like the room's walls.
  constexpr double kDefaultObstacleReflectance = 0.5;
  const double rho = o.has("reflectance") ? o.at("reflectance").as_number_in(0.0, 1.0)
                                          : kDefaultObstacleReflectance;
  if (o.has("box") == o.has("prism")) o.fail("expected exactly one of \"box\" or \"prism\"");
  geometry::Obstacle out;
  if (auto b = o.find("box")) {
    b->expect_object({"min", "max", "rotation_z"});
    const Vec3 lo = b->at("min").as_vec3(), hi = b->at("max").as_vec3();
    const double rot = b->has("rotation_z") ? b->at("rotation_z").as_number() * kDegToRad : 0.0;
    out = at_place(*b, [&] { return geometry::make_box(name, lo, hi, rot, rho); });
  } else {
    const auto p = o.at("prism");
    p.expect_object({"outline", "z0", "z1"});
    const auto outline_v = p.at("outline");
    geometry::Polygon2 outline;
    for (const auto& c : outline_v.items()) outline.push_back(c.as_vec2());
    const double z0 = p.at("z0").as_number(), z1 = p.at("z1").as_number();
    bool reversed = false;
    out = at_place(outline_v, [&] {
      return geometry::make_prism(name, outline, z0, z1, rho, &reversed);
    });
    if (reversed) {
      warnings.push_back("obstacle \"" + name + "\": the outline is clockwise; reversed to counter-clockwise");
    }
  }
  const double top = room.floor_z + room.height;
  if (!(out.z1 > room.floor_z && out.z0 < top) ||
      !geometry::polygons_overlap(out.footprint, room.outline)) {
    o.fail("obstacle \"" + name + "\" lies outside room \"" + room.name + "\"");
  }
  return out;
}

Room parse_room(const JsonValue& r, std::vector<std::string>& warnings) {
  r.expect_object({"name", "outline", "floor_z", "height", "reflectance", "obstacles"});
  Room room;
  room.name = r.at("name").as_string();
  const auto outline = r.at("outline");
  for (const auto& p : outline.items()) room.outline.push_back(p.as_vec2());
  if (room.outline.size() < 3) {
    outline.fail("expected at least 3 corners, got " + std::to_string(room.outline.size()));
  }
  const bool reversed = at_place(outline, [&] {
    return geometry::normalize_outline(room.outline, "room \"" + room.name + "\"");
  });
  if (reversed) {
    warnings.push_back("room \"" + room.name + "\": the outline is clockwise; reversed to counter-clockwise");
  }
  if (auto z = r.find("floor_z")) room.floor_z = z->as_number();
  room.height = r.at("height").as_positive();
  if (auto refl = r.find("reflectance")) {
    refl->expect_object({"floor", "walls", "ceiling"});
    if (auto f = refl->find("floor")) room.reflectance.floor = f->as_number_in(0.0, 1.0);
    if (auto w = refl->find("walls")) room.reflectance.walls = w->as_number_in(0.0, 1.0);
    if (auto c = refl->find("ceiling")) room.reflectance.ceiling = c->as_number_in(0.0, 1.0);
  }
  if (auto obstacles = r.find("obstacles")) {
    size_t index = 0;
    for (const auto& o : obstacles->items()) {
      room.obstacles.push_back(parse_obstacle(o, index++, room, warnings));
      for (size_t k = 0; k + 1 < room.obstacles.size(); ++k) {
        if (room.obstacles[k].name == room.obstacles.back().name) {
          o.at("name").fail("an obstacle named \"" + room.obstacles.back().name +
                            "\" already exists in room \"" + room.name + "\"");
        }
      }
    }
  }
  return room;
}

glm::dmat3 parse_rotation(const JsonValue& rot) {
  const auto v = rot.as_numbers(3);
  return rotation_xyz(v[0] * kDegToRad, v[1] * kDegToRad, v[2] * kDegToRad);
}

void parse_luminaire(const JsonValue& l, size_t index, const Scene& scene,
                     std::vector<Luminaire>& out) {
  l.expect_object({"name", "photometry", "position", "rotation", "array", "emitter"});
  const auto ph = l.at("photometry");
  const std::string key = ph.as_string();
  const auto it = scene.photometry.find(key);
  if (it == scene.photometry.end()) ph.fail("no photometry entry named \"" + key + "\"");

  Luminaire base;
  base.label = l.has("name") ? l.at("name").as_string() : "luminaire " + std::to_string(index);
  base.photometry = key;
  base.distribution = it->second.distribution;
  base.opening = it->second.opening;
  if (auto e = l.find("emitter")) base.opening = parse_emitter(*e);
  if (auto r = l.find("rotation")) base.pose.rotation = parse_rotation(*r);

  const bool has_position = l.has("position");
  const bool has_array = l.has("array");
  if (has_position == has_array) l.fail("expected exactly one of \"position\" or \"array\"");
  if (has_position) {
    base.pose.position = l.at("position").as_vec3();
    out.push_back(base);
    return;
  }
  const auto a = l.at("array");
  a.expect_object({"origin", "count", "spacing"});
  const Vec3 origin = a.at("origin").as_vec3();
  const auto count_v = a.at("count");
  const auto counts = count_v.as_numbers(2);
  int n[2];
  for (int k = 0; k < 2; ++k) {
    n[k] = count_v.item(k).as_int();
    if (n[k] < 1 || n[k] > 10000) count_v.item(k).fail("expected a count from 1 to 10000");
  }
  (void)counts;
  const Vec2 spacing = a.at("spacing").as_vec2();
  for (int j = 0; j < n[1]; ++j) {
    for (int i = 0; i < n[0]; ++i) {
      Luminaire lum = base;
      lum.pose.position = origin + Vec3(spacing.x * i, spacing.y * j, 0.0);
      lum.label = base.label + " [" + std::to_string(i) + "," + std::to_string(j) + "]";
      out.push_back(lum);
    }
  }
}

double parse_spacing(const JsonValue& s, const std::optional<JsonValue>& spacing,
                     double longer_side) {
  if (!spacing) s.fail("missing required key \"spacing\" (metres or \"auto\")");
  if (spacing->is_string()) {
    if (spacing->as_string() != "auto") spacing->fail("expected a number of metres or \"auto\"");
    return geometry::auto_spacing(longer_side);
  }
  return spacing->as_positive();
}

void check_grid_budget(const JsonValue& where, double size_u, double size_v, double spacing) {
  const double points = std::ceil(size_u / spacing) * std::ceil(size_v / spacing);
  if (points > kMaxGridPoints) {
    where.fail("the grid would have " + std::to_string(static_cast<long long>(points)) +
               " points, more than the limit of " +
               std::to_string(static_cast<long long>(kMaxGridPoints)) + "; use a larger spacing");
  }
}

const Room& find_room(const JsonValue& where, const Scene& scene, const std::string& name) {
  for (const auto& r : scene.rooms) {
    if (r.name == name) return r;
  }
  where.fail("no room named \"" + name + "\"");
}

size_t active_points(const geometry::SurfaceGrid& g) {
  size_t n = 0;
  for (bool a : g.active) n += a;
  return n;
}

// "quantity" and "facing": what the numbers of a surface mean (geometry::Quantity). Horizontal
// and vertical replace the receiver normals; cylindrical keeps them (the calculation ignores
// them for E_cyl).
void apply_quantity(const JsonValue& s, std::vector<geometry::SurfaceGrid>& grids) {
  const auto q = s.find("quantity");
  const auto facing = s.find("facing");
  geometry::Quantity quantity = geometry::Quantity::planar;
  if (q) {
    const std::string v = q->as_string();
    if (v == "planar") quantity = geometry::Quantity::planar;
    else if (v == "horizontal") quantity = geometry::Quantity::horizontal;
    else if (v == "vertical") quantity = geometry::Quantity::vertical;
    else if (v == "cylindrical") quantity = geometry::Quantity::cylindrical;
    else q->fail("expected \"planar\", \"horizontal\", \"vertical\" or \"cylindrical\", got \"" + v + "\"");
  }
  if (facing && quantity != geometry::Quantity::vertical) {
    facing->fail("\"facing\" only goes with \"quantity\": \"vertical\"");
  }
  std::optional<Vec3> facing_dir;
  if (facing) {
    const Vec2 f = facing->as_vec2();
    if (glm::length(f) == 0.0) facing->fail("expected a non-zero horizontal direction");
    facing_dir = glm::normalize(Vec3(f.x, f.y, 0.0));
  }
  // A surface normal closer to vertical than this has no usable horizontal direction.
  constexpr double kMinHorizontalPart = 1e-9;
  for (auto& g : grids) {
    g.quantity = quantity;
    for (auto& n : g.normals) {
      if (quantity == geometry::Quantity::horizontal) {
        n = Vec3(0, 0, 1);
      } else if (quantity == geometry::Quantity::vertical) {
        if (facing_dir) {
          n = *facing_dir;
        } else {
          const Vec3 h(n.x, n.y, 0.0);
          if (!(glm::length(h) > kMinHorizontalPart)) {
            q->fail("a vertical quantity on a horizontal surface needs \"facing\": [x, y]");
          }
          n = glm::normalize(h);
        }
      }
    }
  }
}

std::vector<geometry::SurfaceGrid> parse_surface_kind(const JsonValue& s, const Scene& scene,
                                                      const std::string& name) {
  if (auto w = s.find("workplane")) {
    w->expect_object({"room", "height", "border"});
    const auto room_v = w->at("room");
    const Room& room = find_room(room_v, scene, room_v.as_string());
    const auto height_v = w->at("height");
    const double height = height_v.as_non_negative();
    if (height > room.height) height_v.fail("the workplane is above the ceiling of the room");
    const double border = w->has("border") ? w->at("border").as_non_negative() : 0.0;
    // The outline inset by the border (straight skeleton: L-shapes and notches inset right).
    const auto region = geometry::inset_outline(room.outline, border);
    if (region.empty()) w->at("border").fail("the border leaves no workplane inside the room");
    const auto box = geometry::bounds(region);
    const double su = box.hi.x - box.lo.x, sv = box.hi.y - box.lo.y;
    const double spacing = parse_spacing(s, s.find("spacing"), std::max(su, sv));
    check_grid_budget(s, su, sv, spacing);
    auto g = geometry::make_region_grid(name, region, room.floor_z + height, spacing, room.obstacles);
    if (active_points(g) == 0) {
      s.fail("no grid point lies inside the workplane and outside obstacles; use a smaller spacing");
    }
    return {std::move(g)};
  }
  if (auto rs = s.find("room_surfaces")) {
    rs->expect_object({"room"});
    const auto room_v = rs->at("room");
    const Room& room = find_room(room_v, scene, room_v.as_string());
    const auto spacing_v = s.find("spacing");
    if (!spacing_v) s.fail("missing required key \"spacing\" (metres or \"auto\")");
    double spacing = 0.0;  // 0: auto per face
    if (spacing_v->is_string()) {
      if (spacing_v->as_string() != "auto") spacing_v->fail("expected a number of metres or \"auto\"");
    } else {
      spacing = spacing_v->as_positive();
    }
    // Budget over all faces at the finest spacing any face gets (auto: the smaller of the
    // floor's and the shortest face side's rule; a wall's grid is at least one cell long).
    const auto shape = room_shape(room);
    const auto box = geometry::bounds({room.outline});
    double wall_length = 0.0;
    for (size_t k = 0; k < room.outline.size(); ++k) {
      wall_length += glm::length(room.outline[(k + 1) % room.outline.size()] - room.outline[k]);
    }
    const double p = spacing > 0.0 ? spacing
                                   : std::min(geometry::auto_spacing(box.longer_side()),
                                              geometry::auto_spacing(room.height));
    const double points =
        2.0 * std::ceil((box.hi.x - box.lo.x) / p) * std::ceil((box.hi.y - box.lo.y) / p) +
        std::ceil(wall_length / p + static_cast<double>(room.outline.size())) * std::ceil(room.height / p);
    if (points > kMaxGridPoints) {
      s.fail("the grids would have " + std::to_string(static_cast<long long>(points)) +
             " points, more than the limit of " +
             std::to_string(static_cast<long long>(kMaxGridPoints)) + "; use a larger spacing");
    }
    return geometry::make_room_surface_grids(name, shape, spacing, room.obstacles);
  }
  if (auto p = s.find("plane")) {
    p->expect_object({"origin", "u", "v", "size"});
    const Vec3 origin = p->at("origin").as_vec3();
    const auto u_v = p->at("u"), v_v = p->at("v");
    const Vec3 u = u_v.as_vec3(), v = v_v.as_vec3();
    if (glm::length(u) == 0.0) u_v.fail("expected a non-zero direction");
    if (glm::length(v) == 0.0) v_v.fail("expected a non-zero direction");
    const Vec3 un = glm::normalize(u), vn = glm::normalize(v);
    if (std::abs(glm::dot(un, vn)) > 1e-9) v_v.fail("u and v must be perpendicular");
    const auto size_v = p->at("size");
    const Vec2 size = size_v.as_vec2();
    if (!(size.x > 0.0 && size.y > 0.0)) size_v.fail("expected two positive sizes in metres");
    const double spacing = parse_spacing(s, s.find("spacing"), std::max(size.x, size.y));
    check_grid_budget(s, size.x, size.y, spacing);
    return {geometry::make_plane_grid(name, origin, un, vn, size.x, size.y, spacing)};
  }
  const auto pts = s.at("points");
  if (s.has("spacing")) s.at("spacing").fail("a points surface has no spacing");
  geometry::SurfaceGrid g;
  g.name = name;
  g.kind = geometry::SurfaceGrid::Kind::points;
  for (const auto& p : pts.items()) {
    p.expect_object({"at", "normal"});
    g.points.push_back(p.at("at").as_vec3());
    const auto nv = p.at("normal");
    const Vec3 n = nv.as_vec3();
    if (glm::length(n) == 0.0) nv.fail("expected a non-zero normal");
    g.normals.push_back(glm::normalize(n));
  }
  if (g.points.empty()) pts.fail("expected at least one point");
  g.nu = static_cast<int>(g.points.size());
  g.nv = 1;
  g.active.assign(g.points.size(), true);
  return {std::move(g)};
}

// One surface entry gives one grid, or several for room_surfaces ("<name> floor", ...).
std::vector<geometry::SurfaceGrid> parse_surface(const JsonValue& s, const Scene& scene) {
  // "requirements" (EN 12464-1 checks) belongs to the report: report::parse_requirements reads
  // and validates it from the raw document; the scene does not need it.
  s.expect_object({"name", "workplane", "plane", "points", "room_surfaces", "spacing", "quantity",
                   "facing", "requirements"});
  const std::string name = s.at("name").as_string();
  const int kinds = s.has("workplane") + s.has("plane") + s.has("points") + s.has("room_surfaces");
  if (kinds != 1) {
    if (s.has("room_surfaces")) {
      s.fail("expected exactly one of \"workplane\", \"plane\", \"points\" or \"room_surfaces\"");
    }
    s.fail("expected exactly one of \"workplane\", \"plane\" or \"points\"");
  }
  auto grids = parse_surface_kind(s, scene, name);
  apply_quantity(s, grids);
  return grids;
}

// Luminaires outside every room or inside an obstacle are legal (light may enter through an
// opening later) but usually a typo: warn, naming the luminaire.
void warn_about_luminaires(Scene& scene) {
  if (scene.rooms.empty()) return;
  for (const auto& l : scene.luminaires) {
    const Vec3& p = l.pose.position;
    bool inside = false;
    for (const auto& r : scene.rooms) {
      if (!inside_room(r, p)) continue;
      inside = true;
      for (const auto& o : r.obstacles) {
        if (p.z > o.z0 && p.z < o.z1 &&
            geometry::locate(Vec2(p.x, p.y), o.footprint, 0.0) == geometry::Location::inside) {
          scene.warnings.push_back(l.label + ": inside obstacle \"" + o.name + "\" of room \"" +
                                   r.name + "\"");
        }
      }
    }
    if (!inside) scene.warnings.push_back(l.label + ": outside every room");
  }
}

}  // namespace

Scene parse_project(const nlohmann::json& doc, const std::string& label,
                    const std::filesystem::path& base_dir) {
  const JsonValue root(doc, label, "");
  root.expect_object({"format", "name", "settings", "photometry", "rooms", "luminaires", "surfaces"});
  const auto format = root.at("format");
  if (format.as_string() != kProjectFormat) {
    format.fail(std::string("expected \"") + kProjectFormat + "\", got \"" + format.as_string() + "\"");
  }
  Scene scene;
  scene.name = root.has("name") ? root.at("name").as_string() : "unnamed project";
  if (auto s = root.find("settings")) scene.settings = parse_settings(*s);

  const auto ph = root.at("photometry");
  if (!ph.is_object()) ph.fail("expected an object of named entries, got " + json_type_name(ph.raw()));
  for (const auto& [key, _] : ph.raw().items()) {
    scene.photometry.emplace(key, parse_photometry_entry(ph.at(key.c_str()), base_dir));
  }
  for (const auto& r : root.at("rooms").items()) {
    Room room = parse_room(r, scene.warnings);
    for (const auto& other : scene.rooms) {
      if (other.name == room.name) r.at("name").fail("a room named \"" + room.name + "\" already exists");
    }
    scene.rooms.push_back(std::move(room));
  }
  size_t index = 0;
  for (const auto& l : root.at("luminaires").items()) parse_luminaire(l, index++, scene, scene.luminaires);
  warn_about_luminaires(scene);
  const auto surfaces = root.at("surfaces");
  for (const auto& s : surfaces.items()) {
    for (auto& grid : parse_surface(s, scene)) {
      for (const auto& other : scene.surfaces) {
        if (other.name == grid.name) s.at("name").fail("a surface named \"" + grid.name + "\" already exists");
      }
      scene.surfaces.push_back(std::move(grid));
    }
  }
  if (scene.surfaces.empty()) surfaces.fail("expected at least one calculation surface");
  // IES TILT tables hold for the lamp as measured; a luminaire turned in the scene gets its
  // file's factor at its actual tilt, once, here, so every later stage sees the scaled output.
  apply_tilt_factors(scene);
  return scene;
}

Scene load_project(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot open the project file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(buffer.str());
  } catch (const nlohmann::json::parse_error& e) {
    // nlohmann reports a byte offset; turn it into line:column for people.
    const std::string text = buffer.str();
    size_t line = 1, column = 1;
    for (size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
      if (text[i] == '\n') { ++line; column = 1; } else { ++column; }
    }
    std::string what = e.what();
    const auto colon = what.find("syntax error");
    throw InputError(file.string() + ":" + std::to_string(line) + ":" + std::to_string(column) +
                     ": malformed JSON: " + (colon != std::string::npos ? what.substr(colon) : what));
  }
  Scene scene = parse_project(doc, file.filename().string(), file.parent_path());
  scene.project_file = file;
  return scene;
}

}  // namespace luxgrid::calc
