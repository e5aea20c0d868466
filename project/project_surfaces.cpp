// The project's "surfaces": workplanes, planes, points, room surfaces and observers.
#include "project/project_parts.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "calc/scene_visibility.h"
#include "geometry/workplane.h"
#include "util/output_names.h"

namespace luxgrid::project::parts {

// The loader builds calc's types (Scene, Room, Luminaire, Settings) on every line.
using namespace calc;

// "quantity" and "facing": what the numbers of a surface mean (geometry::Quantity). Horizontal
// and vertical replace the receiver normals; cylindrical keeps them (the calculation ignores
// them for E_cyl); semi-cylindrical sets them to the horizontal direction the half cylinder faces,
// found like a vertical plane's normal.
void apply_quantity(const JsonValue& s, std::vector<geometry::SurfaceGrid>& grids) {
  const auto q = s.find("quantity");
  const auto facing = s.find("facing");
  geometry::Quantity quantity = geometry::Quantity::planar;
  if (q) {
    const std::string v = q->as_string();
    if (v == "planar")
      quantity = geometry::Quantity::planar;
    else if (v == "horizontal")
      quantity = geometry::Quantity::horizontal;
    else if (v == "vertical")
      quantity = geometry::Quantity::vertical;
    else if (v == "cylindrical")
      quantity = geometry::Quantity::cylindrical;
    else if (v == "semi-cylindrical")
      quantity = geometry::Quantity::semi_cylindrical;
    else
      q->fail(
          "expected \"planar\", \"horizontal\", \"vertical\", \"cylindrical\" or "
          "\"semi-cylindrical\", got \"" +
          v + "\"");
  }
  // Both turn the receiver towards a horizontal direction: a vertical plane, a half cylinder.
  const bool faces =
      quantity == geometry::Quantity::vertical || quantity == geometry::Quantity::semi_cylindrical;
  if (facing && !faces) {
    facing->fail("\"facing\" only goes with \"quantity\": \"vertical\" or \"semi-cylindrical\"");
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
      } else if (faces) {
        if (facing_dir) {
          n = *facing_dir;
        } else {
          const Vec3 h(n.x, n.y, 0.0);
          if (!(glm::length(h) > kMinHorizontalPart)) {
            q->fail("a " +
                    std::string(quantity == geometry::Quantity::vertical ? "vertical"
                                                                         : "semi-cylindrical") +
                    " quantity on a horizontal surface needs \"facing\": [x, y]");
          }
          n = glm::normalize(h);
        }
      }
    }
  }
}

// A unit view direction: non-zero and not vertical (kMinViewHorizontalPart).
Vec3 view_direction(const JsonValue& v) {
  const Vec3 d = point3(v);
  if (glm::length(d) == 0.0) v.fail("expected a non-zero direction");
  const Vec3 n = glm::normalize(d);
  if (!(std::hypot(n.x, n.y) >= kMinViewHorizontalPart)) {
    v.fail(
        "a view direction must not be vertical (the position index measures heights above the "
        "line of sight in the vertical plane through it)");
  }
  return n;
}

// "observers": [{"at": [x, y, z], "directions": [[dx, dy, dz], ...] or N}]: one point per
// (observer, view), its normal the view direction (geometry::SurfaceGrid::Kind::observers).
// "directions": N gives N horizontal directions from +x, counter-clockwise, evenly spaced.
geometry::SurfaceGrid parse_observers(const JsonValue& s, const JsonValue& obs,
                                      const std::string& name, GridBudget& budget) {
  for (const char* key : {"spacing", "quantity", "facing"}) {
    if (s.has(key)) s.at(key).fail(std::string("an observers surface has no \"") + key + "\"");
  }
  if (!obs.is_array()) obs.fail("expected an array of observers, got " + json_type_name(obs.raw()));
  check_count(obs, kMaxObservers, "observers");
  if (obs.raw().empty()) obs.fail("expected at least one observer");
  geometry::SurfaceGrid g;
  g.name = name;
  g.kind = geometry::SurfaceGrid::Kind::observers;
  size_t index = 0;
  for (const auto& o : obs.items()) {
    o.expect_object();
    const Vec3 at = point3(o.at("at"));
    const auto dirs = o.at("directions");
    std::vector<Vec3> views;
    if (dirs.is_number()) {
      const double n = dirs.as_number();
      if (!(n >= 1.0 && n <= static_cast<double>(kMaxViewsPerObserver)) || n != std::floor(n)) {
        dirs.fail("expected a whole number of horizontal directions from 1 to " +
                  std::to_string(kMaxViewsPerObserver) + ", got " + dirs.raw().dump());
      }
      const int count = dirs.as_int();
      for (int k = 0; k < count; ++k) {
        // cos(pi / 2) is 6e-17, not 0: snap round-off so +y is written as [0, 1, 0].
        const double a = 2.0 * kPi * k / count;
        const auto snap = [](double c) { return std::abs(c) < 1e-12 ? 0.0 : c; };
        views.emplace_back(snap(std::cos(a)), snap(std::sin(a)), 0.0);
      }
    } else {
      if (!dirs.is_array())
        dirs.fail("expected a number of directions or an array of [dx, dy, dz]");
      check_count(dirs, kMaxViewsPerObserver, "directions");
      if (dirs.raw().empty()) dirs.fail("expected at least one direction");
      for (const auto& d : dirs.items()) views.push_back(view_direction(d));
    }
    budget.spend(dirs, static_cast<double>(views.size()), "observers surface");
    budget.spend_views(dirs, static_cast<double>(views.size()));
    if (budget.count_only()) continue;
    for (const Vec3& v : views) {
      g.points.push_back(at);
      g.normals.push_back(v);
      g.observer.push_back(index);
    }
    ++index;
  }
  g.nu = static_cast<int>(g.points.size());
  g.nv = 1;
  g.active.assign(g.points.size(), true);
  return g;
}

std::vector<geometry::SurfaceGrid> parse_surface_kind(const JsonValue& s, const Scene& scene,
                                                      const std::string& name, GridBudget& budget) {
  if (auto w = s.find("workplane")) {
    w->expect_object();
    const auto room_v = w->at("room");
    const Room& room = find_room(room_v, scene, room_v.as_string());
    const auto height_v = w->at("height");
    const double height = height_v.as_non_negative();
    if (height > room.height) height_v.fail("the workplane is above the ceiling of the room");
    const double border =
        w->has("border") ? (w->at("border").as_non_negative(), coordinate(w->at("border"))) : 0.0;
    // The points at least the border from every wall (geometry/workplane.h).
    const auto region = geometry::inset_region(room.outline, border);
    if (region.polygons.empty())
      w->at("border").fail("the border leaves no workplane inside the room");
    const auto box = geometry::bounds(region.polygons);
    const double su = box.hi.x - box.lo.x, sv = box.hi.y - box.lo.y;
    const double spacing = parse_spacing(s, s.find("spacing"), std::max(su, sv));
    budget.spend_cells(s, su, sv, spacing);
    if (budget.count_only()) return {};
    auto g =
        geometry::make_region_grid(name, region, room.floor_z + height, spacing, room.obstacles);
    if (active_points(g) == 0) {
      s.fail(
          "no grid point lies inside the workplane and outside obstacles; use a smaller spacing");
    }
    return grids_of(std::move(g));
  }
  if (auto rs = s.find("room_surfaces")) {
    rs->expect_object();
    const auto room_v = rs->at("room");
    const Room& room = find_room(room_v, scene, room_v.as_string());
    const auto spacing_v = s.find("spacing");
    if (!spacing_v) s.fail("missing required key \"spacing\" (metres or \"auto\")");
    double spacing = 0.0;  // 0: auto per face
    if (spacing_v->is_string()) {
      if (spacing_v->as_string() != "auto")
        spacing_v->fail("expected a number of metres or \"auto\"");
    } else {
      spacing = spacing_v->as_positive();
    }
    // Budget over all faces at the finest spacing any face gets (auto: the smaller of the
    // floor's and the shortest face side's rule; a wall's grid is at least one cell long).
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
        std::ceil(wall_length / p + static_cast<double>(room.outline.size())) *
            std::ceil(room.height / p);
    budget.spend(s, points, "grids");
    if (budget.count_only()) return {};
    const auto shape = room_shape(room);
    return geometry::make_room_surface_grids(name, shape, spacing, room.obstacles);
  }
  if (auto p = s.find("plane")) {
    p->expect_object();
    const Vec3 origin = point3(p->at("origin"));
    const auto u_v = p->at("u"), v_v = p->at("v");
    const Vec3 u = point3(u_v), v = point3(v_v);
    if (glm::length(u) == 0.0) u_v.fail("expected a non-zero direction");
    if (glm::length(v) == 0.0) v_v.fail("expected a non-zero direction");
    const Vec3 un = glm::normalize(u), vn = glm::normalize(v);
    if (std::abs(glm::dot(un, vn)) > 1e-9) v_v.fail("u and v must be perpendicular");
    const auto size_v = p->at("size");
    const Vec2 size = point2(size_v);
    if (!(size.x > 0.0 && size.y > 0.0)) size_v.fail("expected two positive sizes in metres");
    const double spacing = parse_spacing(s, s.find("spacing"), std::max(size.x, size.y));
    budget.spend_cells(s, size.x, size.y, spacing);
    if (budget.count_only()) return {};
    return grids_of(geometry::make_plane_grid(name, origin, un, vn, size.x, size.y, spacing));
  }
  if (auto obs = s.find("observers")) return grids_of(parse_observers(s, *obs, name, budget));
  if (s.has("escape_route") || s.has("open_area"))
    return parse_emergency_surface(s, scene, name, budget);
  const auto pts = s.at("points");
  if (s.has("spacing")) s.at("spacing").fail("a points surface has no spacing");
  if (pts.is_array()) budget.spend(pts, static_cast<double>(pts.raw().size()), "points surface");
  if (budget.count_only()) return {};
  geometry::SurfaceGrid g;
  g.name = name;
  g.kind = geometry::SurfaceGrid::Kind::points;
  for (const auto& p : pts.items()) {
    p.expect_object();
    g.points.push_back(point3(p.at("at")));
    const auto nv = p.at("normal");
    const Vec3 n = point3(nv);
    if (glm::length(n) == 0.0) nv.fail("expected a non-zero normal");
    g.normals.push_back(glm::normalize(n));
  }
  if (g.points.empty()) pts.fail("expected at least one point");
  g.nu = static_cast<int>(g.points.size());
  g.nv = 1;
  g.active.assign(g.points.size(), true);
  return grids_of(std::move(g));
}

// One surface entry gives one grid, or several for room_surfaces ("<name> floor", ...).
// A surface's name becomes its output file names; kMaxSurfaceNameLength keeps them short enough.
void check_name_length(const JsonValue& where, const std::string& name) {
  if (name.empty())
    where.fail("expected a surface name, got an empty one (it names the surface's output files)");
  if (name.size() > kMaxSurfaceNameLength) {
    where.fail("the surface name is " + std::to_string(name.size()) +
               " characters long, more than the limit of " + std::to_string(kMaxSurfaceNameLength) +
               " (it names the surface's output files)");
  }
}

void OutputNames::claim(const JsonValue& where, const std::string& surface) {
  const SurfaceOutputFiles files = surface_output_files(surface);
  for (const std::string* file : files.all()) {
    std::string key = *file;
    for (char& c : key) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (key.front() == '.') {
      where.fail("surface \"" + surface + "\" would write the hidden file " + *file +
                 "; start its name with a letter or digit");
    }
    for (const char* reserved : kFolderOutputFiles) {
      if (key == reserved) {
        where.fail("surface \"" + surface + "\" would write " + *file +
                   ", which the output folder uses for itself; rename the surface");
      }
    }
    const auto [it, fresh] = owner_.emplace(key, surface);
    if (!fresh) {
      where.fail("surface \"" + surface + "\" would write " + *file + ", which surface \"" +
                 it->second + "\" also writes (output file names ignore case and turn characters " +
                 "other than letters, digits, '-', '_' and '.' into '_'); rename one of them");
    }
  }
}

std::vector<geometry::SurfaceGrid> parse_surface(const JsonValue& s, const Scene& scene,
                                                 GridBudget& budget) {
  // "requirements" (EN 12464-1 checks) is read by parse_project into Project::requirements.
  s.expect_object();
  const std::string name = s.at("name").as_string();
  check_name_length(s.at("name"), name);
  const int kinds = s.has("workplane") + s.has("plane") + s.has("points") + s.has("room_surfaces") +
                    s.has("observers") + s.has("escape_route") + s.has("open_area");
  if (kinds != 1 && (s.has("escape_route") || s.has("open_area"))) {
    s.fail(
        "expected exactly one of \"workplane\", \"plane\", \"points\", \"room_surfaces\", "
        "\"observers\", "
        "\"escape_route\" or \"open_area\"");
  }
  if (kinds != 1) {
    if (s.has("room_surfaces")) {
      s.fail("expected exactly one of \"workplane\", \"plane\", \"points\" or \"room_surfaces\"");
    }
    if (s.has("observers")) {
      s.fail("expected exactly one of \"workplane\", \"plane\", \"points\" or \"observers\"");
    }
    s.fail("expected exactly one of \"workplane\", \"plane\" or \"points\"");
  }
  auto grids = parse_surface_kind(s, scene, name, budget);
  if (!s.has("escape_route") && !s.has("open_area")) apply_quantity(s, grids);
  return grids;
}

// UGR (calc/glare) divides by the background luminance from reflected light and by each
// luminaire's projected luminous area: an observers surface refuses a project that turns
// reflections off or has a luminaire without a luminous area (a point emitter).
void check_observers_inputs(const JsonValue& s, const Scene& scene) {
  if (!s.has("observers")) return;
  if (scene.settings.indirect == IndirectMode::off) {
    s.fail(
        "an observers surface needs reflected light: UGR's background luminance is the indirect "
        "illuminance at the eye over pi (CIE 117), and \"settings\": {\"indirect\": \"off\"} "
        "leaves it 0; set \"indirect\" to \"auto\" or \"on\"");
  }
  for (const auto& l : scene.luminaires) {
    if (l.opening.shape == photometry::LuminousOpening::Shape::point) {
      s.fail(
          "an observers surface needs every luminaire's luminous area (UGR's luminance is the "
          "intensity over the projected area); " +
          l.label + " has a point emitter: give it an \"emitter\" with its luminous opening");
    }
  }
}

}  // namespace luxgrid::project::parts
