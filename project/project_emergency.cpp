// Emergency lighting in a project [EN1838]: a luminaire's emergency output and the
// escape_route and open_area surfaces.
#include "project/project_parts.h"

#include <algorithm>

#include "calc/emergency_surfaces.h"
#include "calc/scaled_distribution.h"
#include "geometry/workplane.h"

namespace luxgrid::project::parts {

// The loader builds calc's types (Scene, Room, Luminaire, Settings) on every line.
using namespace calc;

// A luminaire's "emergency" entry [EN1838]: {"fraction": f} of its output (0 < f <= 1),
// {"flux_lm": F} (its own distribution scaled to F lumens, at most its normal flux) or
// {"photometry": "key"} (a separate photometry entry, e.g. the emergency module's own file).
EmergencyOutput parse_emergency_output(const JsonValue& e, const Scene& scene,
                                       const photometry::Photometry& own) {
  if (!e.is_object())
    e.fail("expected {\"fraction\": f}, {\"flux_lm\": F} or {\"photometry\": \"key\"}, got " +
           json_type_name(e.raw()));
  e.expect_object();
  if (e.raw().size() != 1)
    e.fail("expected exactly one of \"fraction\", \"flux_lm\" or \"photometry\"");
  EmergencyOutput out;
  if (auto f = e.find("fraction")) {
    out.factor = f->as_number_in(0.0, 1.0);
    if (!(out.factor > 0.0)) f->fail("expected a fraction in (0, 1], got 0");
  } else if (auto fl = e.find("flux_lm")) {
    const double target = fl->as_positive();
    const double have = luminous_flux(*own.distribution);
    if (!(have > 0.0))
      fl->fail("cannot scale to flux_lm: the luminaire's distribution emits no light");
    if (target > have) {
      fl->fail("the emergency flux " + number_text(target) +
               " lm is more than the luminaire's own " + number_text(have) +
               " lm; for a separate emergency distribution give {\"photometry\": \"key\"}");
    }
    out.factor = target / have;
    out.flux_lm = target;
  } else {
    const auto p = e.at("photometry");
    out.photometry = p.as_string();
    if (!scene.photometry.count(out.photometry))
      p.fail("no photometry entry named \"" + out.photometry + "\"");
  }
  return out;
}

// EN 1838 surfaces (calc/emergency_surfaces.h), on the floor, horizontal illuminance:
// "escape_route": {"path": [[x, y], ...], "width": w, "floor_z": z} gives the grids
// "<name> centre line" and "<name> band"; "open_area": {"room": r, "outline": [[x, y], ...]} the
// room's floor (or the outline's, at the room's floor) without a 0.5 m border.
std::vector<geometry::SurfaceGrid> parse_emergency_surface(const JsonValue& s, const Scene& scene,
                                                           const std::string& name,
                                                           GridBudget& budget) {
  for (const char* key : {"quantity", "facing"}) {
    if (s.has(key))
      s.at(key).fail(
          std::string(
              "an EN 1838 surface measures horizontal illuminance on the floor; it has no \"") +
          key + "\"");
  }
  if (auto r = s.find("escape_route")) {
    r->expect_object();
    const auto path_v = r->at("path");
    if (!path_v.is_array())
      path_v.fail("expected an array of [x, y] corners, got " + json_type_name(path_v.raw()));
    check_count(path_v, kMaxEscapeRouteCorners, "corners");
    geometry::Polygon2 path;
    for (const auto& p : path_v.items()) {
      path.push_back(point2(p));
      // A segment shorter than 1 mm has no usable direction (its band would point anywhere).
      constexpr double kMinSegment_m = 1e-3;
      if (path.size() > 1 && glm::length(path.back() - path[path.size() - 2]) < kMinSegment_m) {
        p.fail("the corner repeats the one before it");
      }
    }
    if (path.size() < 2) path_v.fail("expected at least 2 corners (the route's centre line)");
    const auto width_v = r->at("width");
    const double width = positive_length(width_v);
    if (width > kMaxEscapeRouteWidth_m) {
      width_v.fail("EN 1838's escape-route rules hold for routes up to " +
                   number_text(kMaxEscapeRouteWidth_m) + " m wide, got " + number_text(width) +
                   " m; give a wider route as several routes of at most " +
                   number_text(kMaxEscapeRouteWidth_m) + " m, or as an open_area");
    }
    const double z = r->has("floor_z") ? coordinate(r->at("floor_z")) : 0.0;
    const double spacing = parse_spacing(s, s.find("spacing"), path_length(path));
    budget.spend(s, escape_route_point_count(path, width, spacing), "escape route");
    if (budget.count_only()) return {};
    const EscapeRoutePoints points = escape_route_points(path, width, spacing);
    return grids_of(floor_points_grid(name + " centre line", points.centre_line, z),
                    floor_points_grid(name + " band", points.band, z));
  }
  const auto a = s.at("open_area");
  a.expect_object();
  const auto room_v = a.at("room");
  const Room& room = find_room(room_v, scene, room_v.as_string());
  geometry::Polygon2 outline = room.outline;
  if (auto o = a.find("outline")) {
    outline.clear();
    check_count(*o, kMaxOutlineCorners, "corners");
    for (const auto& p : o->items()) outline.push_back(point2(p));
    if (outline.size() < 3)
      o->fail("expected at least 3 corners, got " + std::to_string(outline.size()));
    // Either orientation: reversed to counter-clockwise quietly (the outline only bounds the grid).
    (void)at_place(
        *o, [&] { return geometry::normalize_outline(outline, "open area \"" + name + "\""); });
  }
  const auto region = geometry::inset_region(outline, kOpenAreaBorder_m);
  if (region.polygons.empty())
    a.fail("the 0.5 m border that EN 1838 leaves out of an open area leaves no core area");
  const auto box = geometry::bounds(region.polygons);
  const double su = box.hi.x - box.lo.x, sv = box.hi.y - box.lo.y;
  const double spacing = parse_spacing(s, s.find("spacing"), std::max(su, sv));
  budget.spend_cells(s, su, sv, spacing);
  if (budget.count_only()) return {};
  auto g = geometry::make_region_grid(name, region, room.floor_z, spacing, room.obstacles);
  g.quantity = geometry::Quantity::horizontal;
  if (active_points(g) == 0)
    s.fail(
        "no grid point lies inside the open area's core and outside obstacles; use a smaller "
        "spacing");
  return grids_of(std::move(g));
}

// The EN 1838 role of each grid an escape_route or open_area entry gave (in
// parse_emergency_surface's order).
void record_emergency_surfaces(const JsonValue& s, const std::vector<geometry::SurfaceGrid>& grids,
                               std::vector<EmergencySurface>& out) {
  const std::string entry = s.at("name").as_string();
  if (s.has("escape_route")) {
    out.push_back({grids.at(0).name, entry, EmergencyRole::route_centre_line});
    out.push_back({grids.at(1).name, entry, EmergencyRole::route_band});
  } else if (s.has("open_area")) {
    out.push_back({grids.at(0).name, entry, EmergencyRole::open_area});
  }
}

}  // namespace luxgrid::project::parts
