#include "calc/opening_placement.h"

#include <cmath>

#include "geometry/polygon.h"
#include "util/format.h"

namespace luxgrid::calc {
namespace {

std::string face_name(const RoomFaceRef& face) {
  switch (face.kind) {
    case RoomFaceRef::Kind::floor: return "the floor";
    case RoomFaceRef::Kind::ceiling: return "the ceiling";
    case RoomFaceRef::Kind::wall: return "wall " + std::to_string(face.wall);
  }
  return "";
}

// The face's outline in its own coordinates (face_coordinates), counter-clockwise.
std::vector<Vec2> face_outline(const Room& room, const RoomFaceRef& face) {
  if (face.kind != RoomFaceRef::Kind::wall) return room.outline;
  const Vec2 a = room.outline[face.wall];
  const Vec2 b = room.outline[(face.wall + 1) % room.outline.size()];
  const double length = glm::length(b - a);
  return {{0.0, room.floor_z},
          {length, room.floor_z},
          {length, room.floor_z + room.height},
          {0.0, room.floor_z + room.height}};
}

bool all_in_plane(const std::vector<Vec3>& polygon, const Vec3& point, const Vec3& normal) {
  for (const Vec3& p : polygon)
    if (std::abs(glm::dot(p - point, normal)) > kOpeningPlaneTolerance_m) return false;
  return true;
}

}  // namespace

std::vector<Vec2> face_coordinates(const Room& room, const RoomFaceRef& face,
                                   const std::vector<Vec3>& polygon) {
  std::vector<Vec2> out;
  out.reserve(polygon.size());
  if (face.kind != RoomFaceRef::Kind::wall) {
    for (const Vec3& p : polygon) out.push_back({p.x, p.y});
    return out;
  }
  const Vec2 a = room.outline[face.wall];
  const Vec2 b = room.outline[(face.wall + 1) % room.outline.size()];
  const Vec2 along = (b - a) / glm::length(b - a);
  for (const Vec3& p : polygon) out.push_back({glm::dot(Vec2{p.x, p.y} - a, along), p.z});
  return out;
}

OpeningPlacement place_opening(const Room& room, const std::vector<Vec3>& polygon) {
  std::vector<std::pair<RoomFaceRef, Vec3>> candidates;  // faces whose plane holds the polygon
  const double ceiling_z = room.floor_z + room.height;
  if (all_in_plane(polygon, Vec3{0, 0, room.floor_z}, Vec3{0, 0, 1}))
    candidates.push_back({{RoomFaceRef::Kind::floor, 0}, Vec3{0, 0, 1}});
  if (all_in_plane(polygon, Vec3{0, 0, ceiling_z}, Vec3{0, 0, 1}))
    candidates.push_back({{RoomFaceRef::Kind::ceiling, 0}, Vec3{0, 0, -1}});
  const size_t n = room.outline.size();
  for (size_t k = 0; k < n; ++k) {
    const Vec2 a = room.outline[k], b = room.outline[(k + 1) % n];
    const Vec2 d = b - a;
    if (!(glm::length(d) > 0.0)) continue;
    // A counter-clockwise outline has its interior on the left of each edge.
    const Vec2 inward2 = Vec2{-d.y, d.x} / glm::length(d);
    const Vec3 inward{inward2.x, inward2.y, 0.0};
    if (all_in_plane(polygon, Vec3{a.x, a.y, 0.0}, inward))
      candidates.push_back({{RoomFaceRef::Kind::wall, k}, inward});
  }
  OpeningPlacement out;
  if (candidates.empty()) {
    out.reason = "lies in the plane of no face of room \"" + room.name +
                 "\" (every corner must lie in the plane of one floor, ceiling or wall, within " +
                 format_number(kOpeningPlaneTolerance_m * 1e3) + " mm)";
    return out;
  }
  for (const auto& [face, inward] : candidates) {
    const std::vector<Vec2> outline = face_outline(room, face);
    const std::vector<Vec2> corners = face_coordinates(room, face, polygon);
    bool inside = true;
    for (const Vec2& c : corners)
      if (geometry::locate(c, outline, kOpeningPlaneTolerance_m) == geometry::Location::outside)
        inside = false;
    // Corners inside a non-convex face do not keep the edges inside: no edge of the opening may
    // cross the face's outline.
    for (size_t i = 0; inside && i < corners.size(); ++i)
      for (size_t j = 0; inside && j < outline.size(); ++j)
        if (geometry::segments_cross(corners[i], corners[(i + 1) % corners.size()], outline[j],
                                     outline[(j + 1) % outline.size()]))
          inside = false;
    if (inside) {
      out.found = true, out.face = face, out.inward_normal = inward;
      return out;
    }
  }
  out.reason = "crosses the edge of " + face_name(candidates.front().first) + " of room \"" +
               room.name + "\" (an opening must lie within its face)";
  return out;
}

}  // namespace luxgrid::calc
