// The project's "rooms": outlines, heights, reflectances and obstacles.
#include "project/project_parts.h"

#include "geometry/prism_union.h"
#include "geometry/workplane.h"
#include "util/degrees.h"

namespace luxgrid::project::parts {

// The loader builds calc's types (Scene, Room, Luminaire, Settings) on every line.
using namespace calc;

geometry::Obstacle parse_obstacle(const JsonValue& o, size_t index, const Room& room,
                                  std::vector<Warning>& warnings) {
  o.expect_object();
  const std::string name =
      o.has("name") ? o.at("name").as_string() : "obstacle " + std::to_string(index);
  // Furniture and columns: mid-grey unless given, like the room's walls.
  constexpr double kDefaultObstacleReflectance = 0.5;
  const double rho = o.has("reflectance") ? o.at("reflectance").as_number_in(0.0, 1.0)
                                          : kDefaultObstacleReflectance;
  if (o.has("box") == o.has("prism")) o.fail("expected exactly one of \"box\" or \"prism\"");
  geometry::Obstacle out;
  if (auto b = o.find("box")) {
    b->expect_object();
    const Vec3 lo = point3(b->at("min")), hi = point3(b->at("max"));
    // Reduced to one turn first (util/degrees.h): 1e300 degrees is a rotation like any other.
    const double rot =
        b->has("rotation_z") ? reduce_degrees(b->at("rotation_z").as_number()) * kDegToRad : 0.0;
    out = at_place(*b, [&] { return geometry::make_box(name, lo, hi, rot, rho); });
  } else {
    const auto p = o.at("prism");
    p.expect_object();
    const auto outline_v = p.at("outline");
    geometry::Polygon2 outline;
    check_count(outline_v, kMaxOutlineCorners, "corners");
    for (const auto& c : outline_v.items()) outline.push_back(point2(c));
    const double z0 = coordinate(p.at("z0")), z1 = coordinate(p.at("z1"));
    bool reversed = false;
    out = at_place(outline_v,
                   [&] { return geometry::make_prism(name, outline, z0, z1, rho, &reversed); });
    if (reversed) {
      warnings.push_back(
          {outline_v.location(),
           "obstacle \"" + name + "\": the outline is clockwise; reversed to counter-clockwise"});
    }
  }
  const double top = room.floor_z + room.height;
  if (!(out.z1 > room.floor_z && out.z0 < top) ||
      !geometry::polygons_overlap(out.footprint, room.outline)) {
    o.fail("obstacle \"" + name + "\" lies outside room \"" + room.name + "\"");
  }
  return out;
}

namespace {

// `"a"`, `"a" and "b"`, `"a", "b" and "c"`: the obstacles a union stands for.
std::string obstacle_names(const Room& room, const std::vector<size_t>& members) {
  std::string out;
  for (size_t k = 0; k < members.size(); ++k) {
    if (k > 0) out += k + 1 == members.size() ? " and " : ", ";
    out += "\"" + room.obstacles[members[k]].name + "\"";
  }
  return out;
}

// Obstacles that overlap or press faces together are replaced by their union (geometry/
// prism_union.h: otherwise each copy of a face reflects, and the room gets light twice), with a
// warning at the second member; a group whose union is no prism is refused at the second of the
// first two members that meet, naming both and what to do.
void unite_overlapping_obstacles(const JsonValue& obstacles, Room& room,
                                 std::vector<Warning>& warnings) {
  geometry::ObstacleUnion u = geometry::unite_obstacles(room.obstacles);
  if (u.conflict) {
    const auto& c = *u.conflict;
    const bool overlap = c.contact == geometry::PrismContact::overlap;
    obstacles.items()[c.second].fail(
        "obstacles " + obstacle_names(room, {c.first, c.second}) + " of room \"" + room.name +
        "\" " + (overlap ? "overlap" : "touch with faces pressed together") +
        ", and their union is no single box or prism (luxgrid unites only obstacles with the "
        "same reflectance and either the same z0 and z1 and outlines that join without a hole, "
        "or the same outline); give the union as one \"prism\", or move them apart");
  }
  for (size_t k = 0; k < u.members.size(); ++k) {
    const std::vector<size_t>& m = u.members[k];
    if (m.size() < 2) continue;
    warnings.push_back({obstacles.items()[m[1]].location(),
                        "obstacles " + obstacle_names(room, m) + " of room \"" + room.name +
                            "\" overlap or touch with faces pressed together; calculated as "
                            "their union, one obstacle named \"" +
                            room.obstacles[m[0]].name + "\""});
  }
  room.obstacles = std::move(u.obstacles);
}

}  // namespace

Room parse_room(const JsonValue& r, std::vector<Warning>& warnings) {
  r.expect_object();
  Room room;
  room.name = r.at("name").as_string();
  const auto outline = r.at("outline");
  check_count(outline, kMaxOutlineCorners, "corners");
  for (const auto& p : outline.items()) room.outline.push_back(point2(p));
  if (room.outline.size() < 3) {
    outline.fail("expected at least 3 corners, got " + std::to_string(room.outline.size()));
  }
  const bool reversed = at_place(outline, [&] {
    return geometry::normalize_outline(room.outline, "room \"" + room.name + "\"");
  });
  if (reversed) {
    warnings.push_back(
        {outline.location(),
         "room \"" + room.name + "\": the outline is clockwise; reversed to counter-clockwise"});
  }
  if (auto z = r.find("floor_z")) room.floor_z = coordinate(*z);
  const auto height_v = r.at("height");
  room.height = positive_length(height_v);
  if (room.height > kMaxRoomHeight_m) {
    // Refused before any grid or patch is sized by it: a project in millimetres would otherwise
    // calculate a room a thousand times too large (minutes, gigabytes, and 0.0003 lx).
    height_v.fail("the room \"" + room.name + "\" is " + number_text(room.height) +
                  " m high, more than the limit of " + number_text(kMaxRoomHeight_m) +
                  " m for a room; the lengths look like millimetres, and luxgrid reads metres "
                  "(divide them by 1000)");
  }
  if (auto refl = r.find("reflectance")) {
    refl->expect_object();
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
    unite_overlapping_obstacles(*obstacles, room, warnings);
  }
  return room;
}

}  // namespace luxgrid::project::parts
