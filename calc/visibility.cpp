#include "calc/visibility.h"

namespace luxgrid::calc {

namespace {
std::string plural(size_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}
}  // namespace

geometry::RoomShape room_shape(const Room& room) {
  return geometry::RoomShape{room.name,
                             room.outline,
                             room.floor_z,
                             room.height,
                             room.reflectance.floor,
                             room.reflectance.walls,
                             room.reflectance.ceiling};
}

std::vector<geometry::Face> scene_faces(const Scene& scene) {
  std::vector<geometry::Face> faces;
  for (const auto& room : scene.rooms) {
    auto f = geometry::room_faces(room_shape(room));
    faces.insert(faces.end(), f.begin(), f.end());
    for (const auto& o : room.obstacles) {
      auto of = geometry::obstacle_faces(o);
      faces.insert(faces.end(), of.begin(), of.end());
    }
  }
  return faces;
}

bool inside_room(const Room& room, const Vec3& p, double tolerance_m) {
  if (p.z < room.floor_z - tolerance_m) return false;
  if (p.z > room.floor_z + room.height + tolerance_m) return false;
  return geometry::locate(Vec2(p.x, p.y), room.outline, tolerance_m) != geometry::Location::outside;
}

std::unique_ptr<geometry::OcclusionTree> make_visibility(const Scene& scene, std::string& reason) {
  std::vector<std::string> why;
  size_t obstacles = 0;
  for (const auto& r : scene.rooms) obstacles += r.obstacles.size();
  if (obstacles > 0) why.push_back(plural(obstacles, "obstacle", "obstacles"));
  if (scene.rooms.size() > 1) why.push_back(std::to_string(scene.rooms.size()) + " rooms");
  for (const auto& r : scene.rooms) {
    if (!geometry::is_convex(r.outline)) why.push_back("non-convex room '" + r.name + "'");
  }
  auto in_some_room = [&](const Vec3& p) {
    for (const auto& r : scene.rooms) {
      if (inside_room(r, p)) return true;
    }
    return false;
  };
  if (!scene.rooms.empty()) {
    size_t outside = 0;
    std::string first;
    for (const auto& l : scene.luminaires) {
      if (!in_some_room(l.pose.position)) {
        if (outside++ == 0) first = l.label;
      }
    }
    if (outside == 1) why.push_back(first + " outside every room");
    if (outside > 1) why.push_back(std::to_string(outside) + " luminaires outside every room");
    // An opening that reaches through a wall: the walls must hide its part outside the room
    // (the corners of its bounding rectangle, in the luminaire's local z = 0 plane).
    size_t reaching = 0;
    for (const auto& l : scene.luminaires) {
      if (l.opening.shape == photometry::LuminousOpening::Shape::point ||
          !in_some_room(l.pose.position))
        continue;
      bool out = false;
      for (const double sx : {-0.5, 0.5}) {
        for (const double sy : {-0.5, 0.5}) {
          const Vec3 corner = l.pose.position + l.pose.rotation * Vec3(sx * l.opening.length,
                                                                       sy * l.opening.width, 0.0);
          out = out || !in_some_room(corner);
        }
      }
      if (out && reaching++ == 0) first = l.label;
    }
    if (reaching == 1) why.push_back("the opening of " + first + " reaches outside its room");
    if (reaching > 1)
      why.push_back("the openings of " + std::to_string(reaching) +
                    " luminaires reach outside their rooms");
    size_t points_outside = 0;
    for (const auto& s : scene.surfaces) {
      for (size_t i = 0; i < s.points.size(); ++i) {
        if ((s.active.empty() || s.active[i]) && !in_some_room(s.points[i])) ++points_outside;
      }
    }
    if (points_outside > 0) {
      why.push_back(plural(points_outside, "surface point", "surface points") +
                    " outside every room");
    }
  }
  if (why.empty()) {
    reason = scene.rooms.empty() ? "off: no rooms and no obstacles, nothing can block light"
                                 : "off: convex room, no obstacles, every luminaire inside";
    return nullptr;
  }
  reason = "on:";
  for (size_t i = 0; i < why.size(); ++i) reason += (i ? ", " : " ") + why[i];
  return std::make_unique<geometry::OcclusionTree>(scene_faces(scene));
}

}  // namespace luxgrid::calc
