#include "project/sanity_checks.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "calc/scaled_distribution.h"
#include "calc/scene_visibility.h"
#include "geometry/workplane.h"
#include "photometry/tabular_distribution.h"

namespace luxgrid::project {

// The checks read calc's Scene, rooms and luminaires throughout.
using namespace calc;

namespace {

// `surface "workplane"`: a warning's place is the entry's (file, line, column, pointer); its
// message names the object as the user does.
std::string surface_named(const std::string& name) { return "surface \"" + name + "\""; }

std::string metres(double x) { return number_text(x) + " m"; }

// Lengths in a room's plan or a plane that read as millimetres.
void check_millimetres(const Scene& scene, const JsonValue& root, std::vector<Warning>& out) {
  if (auto rooms = root.find("rooms")) {
    const auto items = rooms->items();
    for (size_t i = 0; i < items.size() && i < scene.rooms.size(); ++i) {
      const Room& r = scene.rooms[i];
      const auto box = geometry::bounds({r.outline});
      const double dx = box.hi.x - box.lo.x, dy = box.hi.y - box.lo.y;
      if (std::max(dx, dy) > kMillimetreSuspect_m) {
        out.push_back(
            {items[i].location(),
             "room \"" + r.name + "\": the room is " + metres(dx) + " x " + metres(dy) +
                 " in plan, which looks like millimetres; luxgrid reads every length in metres "
                 "and calculated the room as given (divide the lengths by 1000)"});
      }
    }
  }
  if (auto surfaces = root.find("surfaces")) {
    for (const auto& s : surfaces->items()) {
      const auto plane = s.find("plane");
      if (!plane) continue;
      const auto size = plane->at("size").as_vec2();
      if (std::max(size.x, size.y) > kMillimetreSuspect_m) {
        out.push_back(
            {s.location(),
             surface_named(s.at("name").as_string()) + ": the plane is " + metres(size.x) + " x " +
                 metres(size.y) +
                 ", which looks like millimetres; luxgrid reads every length in "
                 "metres and calculated the plane as given (divide the lengths by 1000)"});
      }
    }
  }
}

// The grids an entry of "surfaces" produced: one, or the floor, ceiling and walls of
// room_surfaces, which the loader appends in order under the entry's name.
struct SurfaceEntry {
  JsonValue value;
  std::vector<const geometry::SurfaceGrid*> grids;
};

std::vector<SurfaceEntry> surface_entries(const Scene& scene, const JsonValue& root) {
  std::vector<SurfaceEntry> out;
  const auto surfaces = root.find("surfaces");
  if (!surfaces) return out;
  size_t next = 0;
  for (const auto& s : surfaces->items()) {
    SurfaceEntry e{s, {}};
    const std::string name = s.at("name").as_string();
    if (s.has("room_surfaces")) {
      while (next < scene.surfaces.size() && scene.surfaces[next].name.rfind(name + " ", 0) == 0)
        e.grids.push_back(&scene.surfaces[next++]);
    } else if (next < scene.surfaces.size()) {
      e.grids.push_back(&scene.surfaces[next++]);
    }
    out.push_back(std::move(e));
  }
  return out;
}

// A spacing larger than the surface, and grids too coarse for statistics.
void check_grids(const std::vector<SurfaceEntry>& entries, const Scene& scene,
                 std::vector<Warning>& out) {
  for (const auto& e : entries) {
    const std::string name = e.value.at("name").as_string();
    const auto spacing = e.value.find("spacing");
    if (spacing && spacing->is_number() && !e.grids.empty()) {
      double longer = 0.0;
      std::string extent;
      if (auto rs = e.value.find("room_surfaces")) {
        const std::string room = rs->at("room").as_string();
        for (const auto& r : scene.rooms) {
          if (r.name != room) continue;
          const auto box = geometry::bounds({r.outline});
          longer = std::max({box.hi.x - box.lo.x, box.hi.y - box.lo.y, r.height});
          extent = metres(box.hi.x - box.lo.x) + " x " + metres(box.hi.y - box.lo.y) + " x " +
                   metres(r.height);
        }
      } else {
        const auto& g = *e.grids.front();
        longer = std::max(g.size_u, g.size_v);
        extent = metres(g.size_u) + " x " + metres(g.size_v);
      }
      const double p = spacing->as_number();
      if (longer > 0.0 && p > longer) {
        out.push_back({spacing->location(),
                       "the spacing " + metres(p) + " of surface \"" + name +
                           "\" is larger than the surface (" + extent +
                           "); luxgrid used one cell across it (spacings are in metres)"});
      }
    }
    std::string coarse;
    for (const auto* g : e.grids) {
      if (g->kind != geometry::SurfaceGrid::Kind::grid) continue;
      if (g->nu >= kMinGridPointsPerSide && g->nv >= kMinGridPointsPerSide) continue;
      coarse += (coarse.empty() ? "" : ", ") +
                (e.grids.size() > 1 ? g->name + " " : std::string()) + std::to_string(g->nu) +
                " x " + std::to_string(g->nv) + " points";
    }
    if (!coarse.empty()) {
      out.push_back(
          {e.value.location(),
           surface_named(name) + ": a grid of fewer than " + std::to_string(kMinGridPointsPerSide) +
               " x " + std::to_string(kMinGridPointsPerSide) + " points (" + coarse +
               "); luxgrid calculated it as given, but its Emin, U0 and map say little (use a "
               "smaller spacing)"});
    }
  }
}

// A grid whose points all face away from every room: its receivers look at the outside of the
// room's boundary (a wall plane with u and v swapped), where no luminaire of the room shines.
void check_facing(const std::vector<SurfaceEntry>& entries, const Scene& scene,
                  std::vector<Warning>& out) {
  if (scene.rooms.empty()) return;
  auto in_some_room = [&](const Vec3& p) {
    return std::any_of(scene.rooms.begin(), scene.rooms.end(),
                       [&](const Room& r) { return inside_room(r, p); });
  };
  for (const auto& e : entries) {
    for (const auto* g : e.grids) {
      if (g->quantity == geometry::Quantity::cylindrical) continue;  // no facing side
      bool front_inside = false, back_inside = false;
      for (size_t i = 0; i < g->points.size() && !front_inside; ++i) {
        if (!g->active.empty() && !g->active[i]) continue;
        front_inside = in_some_room(g->points[i] + kFacingProbe_m * g->normals[i]);
        back_inside = back_inside || in_some_room(g->points[i] - kFacingProbe_m * g->normals[i]);
      }
      if (front_inside || !back_inside) continue;  // faces a room, or lies outside all of them
      out.push_back(
          {e.value.location(),
           surface_named(e.value.at("name").as_string()) + ": grid \"" + g->name +
               "\" faces out of every room (its normals point through the room's boundary); "
               "luxgrid calculated the light arriving on that side, which no luminaire inside "
               "reaches (swap u and v, or turn the normal, to face into the room)"});
    }
  }
}

// flux_lm in kilolumens: far below what the file itself says the luminaire emits.
void check_flux(const Scene& scene, const JsonValue& root, std::vector<Warning>& out) {
  const auto ph = root.find("photometry");
  if (!ph || !ph->is_object()) return;
  for (const auto& [key, _] : ph->raw().items()) {
    const auto entry = ph->at(key.c_str());
    if (!entry.is_object()) continue;
    const auto flux = entry.find("flux_lm");
    const auto it = scene.photometry.find(key);
    if (!flux || it == scene.photometry.end() || !it->second.table) continue;
    const double target = flux->as_number();
    const double file_lm = luminous_flux(*it->second.table);
    if (target < kKilolumenSuspect_lm && file_lm >= kKilolumenRatio * target) {
      out.push_back(
          {flux->location(), "flux_lm " + number_text(target) + " lm for photometry \"" + key +
                                 "\", whose file gives " + number_text(std::round(file_lm)) +
                                 " lm, looks like kilolumens; luxgrid scaled the luminaire to " +
                                 number_text(target) + " lm (for " + number_text(target * 1000.0) +
                                 " lm write " + number_text(target * 1000.0) + ")"});
    }
  }
}

// Per entry of "luminaires": the luminaires it became, in the scene's order.
std::vector<std::pair<JsonValue, std::vector<const Luminaire*>>> luminaire_entries(
    const Scene& scene, const JsonValue& root) {
  std::vector<std::pair<JsonValue, std::vector<const Luminaire*>>> out;
  const auto list = root.find("luminaires");
  if (!list) return out;
  size_t next = 0;
  for (const auto& l : list->items()) {
    size_t n = 1;
    if (auto a = l.find("array")) {
      const auto c = a->at("count").as_numbers(2);
      n = static_cast<size_t>(c[0]) * static_cast<size_t>(c[1]);
    }
    std::vector<const Luminaire*> members;
    for (size_t k = 0; k < n && next < scene.luminaires.size(); ++k)
      members.push_back(&scene.luminaires[next++]);
    out.emplace_back(l, std::move(members));
  }
  return out;
}

// Rotations are in degrees; small non-whole values within one turn read as radians.
void check_rotation(const JsonValue& l, std::vector<Warning>& out) {
  const auto rot = l.find("rotation");
  if (!rot) return;
  const auto v = rot->as_numbers(3);
  bool within_turn = true, any_nonzero = false, any_fraction = false;
  for (double a : v) {
    within_turn = within_turn && std::abs(a) <= 2.0 * kPi;
    any_nonzero = any_nonzero || a != 0.0;
    any_fraction = any_fraction || a != std::round(a);
  }
  if (!(within_turn && any_nonzero && any_fraction)) return;
  std::string degrees;
  for (double a : v)
    degrees +=
        (degrees.empty() ? "" : ", ") + number_text(std::round(a * kRadToDeg * 100.0) / 100.0);
  out.push_back({rot->location(),
                 "the rotation [" + number_text(v[0]) + ", " + number_text(v[1]) + ", " +
                     number_text(v[2]) +
                     "] looks like radians; luxgrid reads degrees and turned the luminaire by "
                     "that many degrees (in degrees, these radians are [" +
                     degrees + "])"});
}

// The nearest wall of `room` that the ray from `p` along unit `d` meets, m; infinity if none.
double distance_to_wall(const Room& room, const Vec3& p, const Vec3& d, size_t& wall) {
  double best = INFINITY;
  const auto& o = room.outline;
  const Vec2 p2(p.x, p.y), d2(d.x, d.y);
  auto cross = [](const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; };
  for (size_t k = 0; k < o.size(); ++k) {
    const Vec2 a = o[k], e = o[(k + 1) % o.size()] - a;
    const Vec2 inward(-e.y, e.x);  // counter-clockwise outline: the room lies to the left
    if (glm::dot(d2, inward) >= 0.0) continue;  // moving away from the wall or along it
    const double denom = cross(d2, e);
    if (denom == 0.0) continue;
    const double t = cross(a - p2, e) / denom, s = cross(a - p2, d2) / denom;
    if (t < 0.0 || s < 0.0 || s > 1.0) continue;
    const double z = p.z + t * d.z;
    if (z < room.floor_z || z > room.floor_z + room.height) continue;  // above or below the wall
    if (t < best) {
      best = t;
      wall = k;
    }
  }
  return best;
}

void check_aim(const JsonValue& l, const std::vector<const Luminaire*>& members, const Scene& scene,
               std::map<std::string, Vec3>& beams, std::vector<Warning>& out) {
  const Luminaire* first = nullptr;
  size_t hits = 0;
  std::string what;
  for (const auto* lum : members) {
    auto [it, fresh] = beams.emplace(lum->photometry, Vec3(0.0));
    if (fresh) it->second = main_beam_direction(*lum->distribution);
    if (glm::length(it->second) == 0.0) return;
    const Vec3 d = glm::normalize(lum->pose.rotation * it->second);
    for (const auto& r : scene.rooms) {
      if (!inside_room(r, lum->pose.position)) continue;
      size_t wall = 0;
      const double t = distance_to_wall(r, lum->pose.position, d, wall);
      if (!(t < kBeamIntoWall_m)) continue;
      if (!first) {
        first = lum;
        what = "its main beam (direction " + number_text(std::round(d.x * 100) / 100) + ", " +
               number_text(std::round(d.y * 100) / 100) + ", " +
               number_text(std::round(d.z * 100) / 100) + ") meets room \"" + r.name + "\" wall " +
               std::to_string(wall) + " " + metres(std::round(t * 100) / 100) + " away";
      }
      ++hits;
      break;
    }
  }
  if (!first) return;
  out.push_back(
      {l.location(),
       first->label +
           (hits > 1 ? " and " + std::to_string(hits - 1) + " more of this entry" : std::string()) +
           ": " + what +
           "; luxgrid calculated it as placed and turned (check its position and rotation)"});
}

}  // namespace

Vec3 main_beam_direction(const photometry::IntensityDistribution& d) {
  // Midpoint rule over the sphere, 2 x 5 degree cells: the mean direction is a coarse quantity,
  // and a warning threshold of 0.5 m does not need more.
  constexpr int kGamma = 90, kC = 72;
  Vec3 sum(0.0);
  double total = 0.0;
  for (int i = 0; i < kGamma; ++i) {
    const double gamma = (i + 0.5) * kPi / kGamma;
    for (int j = 0; j < kC; ++j) {
      const double c = (j + 0.5) * 2.0 * kPi / kC;
      const Vec3 dir = photometry::direction_of(c, gamma);
      const double w = d.intensity(dir) * std::sin(gamma);
      sum += w * dir;
      total += w;
    }
  }
  // Less than a third of the light in the mean direction: no main beam (isotropic, up-down).
  constexpr double kMinDirectedFraction = 1.0 / 3.0;
  if (!(total > 0.0) || glm::length(sum) < kMinDirectedFraction * total) return Vec3(0.0);
  return glm::normalize(sum);
}

void add_sanity_warnings(Scene& scene, const JsonValue& root) {
  std::vector<Warning> out;
  check_millimetres(scene, root, out);
  const auto entries = surface_entries(scene, root);
  check_grids(entries, scene, out);
  check_facing(entries, scene, out);
  check_flux(scene, root, out);
  std::map<std::string, Vec3> beams;  // per photometry entry
  for (const auto& [l, members] : luminaire_entries(scene, root)) {
    check_rotation(l, out);
    check_aim(l, members, scene, beams, out);
  }
  scene.warnings.insert(scene.warnings.end(), out.begin(), out.end());
}

}  // namespace luxgrid::project
