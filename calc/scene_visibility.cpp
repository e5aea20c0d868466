#include "calc/scene_visibility.h"

namespace luxgrid::calc {

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

std::unique_ptr<geometry::OcclusionTree> make_visibility(const Scene& scene,
                                                         VisibilityDecision& d) {
  d = VisibilityDecision{};
  for (const auto& r : scene.rooms) d.obstacles += r.obstacles.size();
  if (scene.rooms.size() > 1) d.rooms = scene.rooms.size();
  for (const auto& r : scene.rooms) {
    if (!geometry::is_convex(r.outline)) d.non_convex_rooms.push_back(r.name);
  }
  auto in_some_room = [&](const Vec3& p) {
    for (const auto& r : scene.rooms) {
      if (inside_room(r, p)) return true;
    }
    return false;
  };
  if (!scene.rooms.empty()) {
    for (const auto& l : scene.luminaires) {
      if (!in_some_room(l.pose.position)) {
        if (d.luminaires_outside++ == 0) d.first_outside = l.label;
      }
    }
    // An opening that reaches through a wall: the walls must hide its part outside the room
    // (the corners of its bounding rectangle, in the luminaire's local z = 0 plane).
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
      if (out && d.openings_reaching++ == 0) d.first_reaching = l.label;
    }
    for (const auto& s : scene.surfaces) {
      for (size_t i = 0; i < s.points.size(); ++i) {
        if ((s.active.empty() || s.active[i]) && !in_some_room(s.points[i])) ++d.points_outside;
      }
    }
  }
  d.on = d.obstacles > 0 || d.rooms > 0 || !d.non_convex_rooms.empty() ||
         d.luminaires_outside > 0 || d.openings_reaching > 0 || d.points_outside > 0;
  if (!d.on) {
    d.no_rooms = scene.rooms.empty();
    return nullptr;
  }
  return std::make_unique<geometry::OcclusionTree>(scene_faces(scene));
}

}  // namespace luxgrid::calc
