// The project's "luminaires": photometry, emitter, pose, arrays expanded.
#include "project/project_parts.h"

#include <cmath>

#include "calc/scene_visibility.h"
#include "geometry/workplane.h"
#include "util/degrees.h"

namespace luxgrid::project::parts {

// The loader builds calc's types (Scene, Room, Luminaire, Settings) on every line.
using namespace calc;

// An emitter's side or diameter, m, within [kMinEmitterSize_m, kMaxEmitterSize_m].
void check_emitter_size(const JsonValue& where, double size_m) {
  if (size_m < kMinEmitterSize_m || size_m > kMaxEmitterSize_m) {
    where.fail("expected an emitter size from " + number_text(kMinEmitterSize_m) + " to " +
               number_text(kMaxEmitterSize_m) + " m, got " + number_text(size_m) +
               " m (a smaller source is a \"point\")");
  }
}

photometry::LuminousOpening parse_emitter(const JsonValue& e) {
  e.expect_object();
  const auto shape = e.at("shape");
  const std::string s = shape.as_string();
  photometry::LuminousOpening o;
  if (s == "rectangle") {
    if (e.has("diameter")) e.at("diameter").fail("a rectangle takes \"size\", not \"diameter\"");
    const auto size = e.at("size");
    const auto v = size.as_numbers(2);
    if (!(v[0] > 0.0 && v[1] > 0.0)) size.fail("expected two positive sizes in metres");
    check_emitter_size(size.item(0), v[0]);
    check_emitter_size(size.item(1), v[1]);
    o.shape = photometry::LuminousOpening::Shape::rectangle;
    o.length = v[0];
    o.width = v[1];
  } else if (s == "disk") {
    if (e.has("size")) e.at("size").fail("a disk takes \"diameter\", not \"size\"");
    o.shape = photometry::LuminousOpening::Shape::disk;
    const auto diameter = e.at("diameter");
    o.length = o.width = diameter.as_positive();
    check_emitter_size(diameter, o.length);
  } else if (s == "point") {
    if (e.has("size") || e.has("diameter")) e.fail("a point emitter has no size");
    o.shape = photometry::LuminousOpening::Shape::point;
  } else {
    shape.fail("expected \"rectangle\", \"disk\" or \"point\", got \"" + s + "\"");
  }
  return o;
}

glm::dmat3 parse_rotation(const JsonValue& rot) {
  const auto v = rot.as_numbers(3);
  // Reduced to one turn first (util/degrees.h): 1e300 degrees is a rotation like any other.
  return rotation_xyz(reduce_degrees(v[0]) * kDegToRad, reduce_degrees(v[1]) * kDegToRad,
                      reduce_degrees(v[2]) * kDegToRad);
}

// The project's luminaires, arrays expanded, would number `total`.
void check_luminaire_count(const JsonValue& where, size_t total) {
  if (total > kMaxLuminaires) {
    where.fail("the project would have " + std::to_string(total) +
               " luminaires, more than the limit of " + std::to_string(kMaxLuminaires));
  }
}

void parse_luminaire(const JsonValue& l, size_t index, const Scene& scene,
                     std::vector<Luminaire>& out) {
  l.expect_object();
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
  if (auto e = l.find("emergency")) base.emergency = parse_emergency_output(*e, scene, it->second);
  if (auto r = l.find("rotation")) base.pose.rotation = parse_rotation(*r);

  const bool has_position = l.has("position");
  const bool has_array = l.has("array");
  if (has_position == has_array) l.fail("expected exactly one of \"position\" or \"array\"");
  if (has_position) {
    base.pose.position = point3(l.at("position"));
    check_luminaire_count(l, out.size() + 1);
    out.push_back(base);
    return;
  }
  const auto a = l.at("array");
  a.expect_object();
  const Vec3 origin = point3(a.at("origin"));
  const auto count_v = a.at("count");
  count_v.as_numbers(2);
  int n[2];
  for (int k = 0; k < 2; ++k) {
    const auto c = count_v.item(k);
    // In double first: as_int refuses only beyond 1e9, and the product could overflow an int.
    const double x = c.as_number();
    if (!(x >= 1.0 && x <= kMaxArrayCount)) {
      c.fail("expected a count from 1 to " + std::to_string(kMaxArrayCount));
    }
    n[k] = c.as_int();
  }
  // Counted before a single copy is made (10 000 x 10 000 copies took 2.2 GB, then bad_alloc).
  const double members = static_cast<double>(n[0]) * n[1];
  if (members > static_cast<double>(kMaxLuminaires)) {
    count_v.fail("the array has " + count_text(members) + " luminaires, more than the limit of " +
                 std::to_string(kMaxLuminaires) + " in a project");
  }
  check_luminaire_count(count_v, out.size() + static_cast<size_t>(members));
  const auto spacing_v = a.at("spacing");
  const Vec2 spacing = point2(spacing_v);
  // The far corner, too, must lie within the coordinate limit.
  const Vec3 last = origin + Vec3(spacing.x * (n[0] - 1), spacing.y * (n[1] - 1), 0.0);
  for (int k = 0; k < 2; ++k) {
    if (std::abs(last[k]) > kMaxCoordinate_m) {
      spacing_v.fail("the array reaches " + std::string(k == 0 ? "x" : "y") + " = " +
                     number_text(last[k]) + " m, beyond the limit of " +
                     number_text(kMaxCoordinate_m) + " m for coordinates");
    }
  }
  for (int j = 0; j < n[1]; ++j) {
    for (int i = 0; i < n[0]; ++i) {
      Luminaire lum = base;
      lum.pose.position = origin + Vec3(spacing.x * i, spacing.y * j, 0.0);
      lum.label = base.label + " [" + std::to_string(i) + "," + std::to_string(j) + "]";
      out.push_back(lum);
    }
  }
}

// Luminaires outside every room or inside an obstacle are legal (light may enter through an
// opening later) but usually a typo: warn, naming the luminaire.
void warn_about_luminaires(const JsonValue& entry, std::size_t first, Scene& scene) {
  if (scene.rooms.empty()) return;
  for (std::size_t k = first; k < scene.luminaires.size(); ++k) {
    const Luminaire& l = scene.luminaires[k];
    const Vec3& p = l.pose.position;
    bool inside = false;
    for (const auto& r : scene.rooms) {
      if (!inside_room(r, p)) continue;
      inside = true;
      for (const auto& o : r.obstacles) {
        if (p.z > o.z0 && p.z < o.z1 &&
            geometry::locate(Vec2(p.x, p.y), o.footprint, 0.0) == geometry::Location::inside) {
          scene.warnings.push_back({entry.location(), l.label + ": inside obstacle \"" + o.name +
                                                          "\" of room \"" + r.name + "\""});
        }
      }
    }
    if (!inside) scene.warnings.push_back({entry.location(), l.label + ": outside every room"});
  }
}

}  // namespace luxgrid::project::parts
