#include "calc/indirect/emitter_cells.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "calc/indirect/patches.h"
#include "calc/nearfield/emitter.h"

namespace luxgrid::calc::indirect {

namespace {

// A part of the opening no wider than this multiple of kOpeningOnFace_m (area <= width x its
// diameter) is the sliver the moved clip planes leave of an opening flush with the room's
// outside, not light entering. (Not a fraction of the opening: the 4 x 4 m part of a 1e9 m
// emitter is 1.6e-17 of it, and real.)
constexpr double kSliverWidths = 2.0;
// Openings with less than this fraction outside their rooms get no note (rounding of the clip).
constexpr double kOutsideNoteFraction = 1e-6;

// The smallest extent of a room (m): its height, or its outline's width or depth.
double smallest_extent(const Room& room) {
  Vec2 lo = room.outline[0], hi = room.outline[0];
  for (const auto& v : room.outline) lo = glm::min(lo, v), hi = glm::max(hi, v);
  return std::min({room.height, hi.x - lo.x, hi.y - lo.y});
}

// The room as convex prisms: its outline (convex) or the outline's ear triangles, floor to
// ceiling. Their interiors tile the room, so the opening clipped by each tiles opening x room.
// A room whose outline cannot be clipped has no pieces here: build_patch_mesh reports it with
// the room's name (decide_indirect runs before the mesh validates the rooms).
std::vector<Polygon2> convex_pieces(const Room& room) {
  if (room.outline.size() < 3 || !(room.height > 0.0)) return {};
  if (outline_is_convex(room)) return {room.outline};
  return geometry::triangles(room.outline);
}

// `poly` clipped to the prism `piece` x [z0, z1], each plane moved out by kOpeningOnFace_m.
Polygon3 clip_to_prism(Polygon3 poly, const Polygon2& piece, double z0, double z1) {
  poly = geometry::clip_to_half_space(poly, Vec3(0.0, 0.0, z0 - kOpeningOnFace_m),
                                      Vec3(0.0, 0.0, 1.0));
  poly = geometry::clip_to_half_space(poly, Vec3(0.0, 0.0, z1 + kOpeningOnFace_m),
                                      Vec3(0.0, 0.0, -1.0));
  for (size_t k = 0; k < piece.size() && poly.size() >= 3; ++k) {
    const Vec2 a = piece[k], b = piece[(k + 1) % piece.size()];
    const double len = glm::length(b - a);
    if (!(len > 0.0)) continue;
    const Vec3 inward(-(b.y - a.y) / len, (b.x - a.x) / len, 0.0);  // left of a -> b (ccw)
    poly =
        geometry::clip_to_half_space(poly, Vec3(a.x, a.y, 0.0) - inward * kOpeningOnFace_m, inward);
  }
  return poly;
}

// True when `part` lies in the plane of one of the room's faces (within twice kOpeningOnFace_m:
// the clip tolerance) and `emitting` (the opening's emitting normal) points out of the room
// through it. Such an opening is flush with the face and emits into the room on the other side
// (a downlight in the ceiling that is the floor of the room above belongs to the room below),
// so it is counted once, where it emits, as room_containing counted a point once.
bool flush_emitting_out(const Polygon3& part, const Room& room, const Vec3& emitting) {
  auto in_plane = [&](const Vec3& origin, const Vec3& inward) {
    for (const Vec3& v : part)
      if (std::abs(glm::dot(v - origin, inward)) > 2.0 * kOpeningOnFace_m) return false;
    return glm::dot(emitting, inward) < 0.0;
  };
  if (in_plane(Vec3(0.0, 0.0, room.floor_z), Vec3(0.0, 0.0, 1.0))) return true;
  if (in_plane(Vec3(0.0, 0.0, room.floor_z + room.height), Vec3(0.0, 0.0, -1.0))) return true;
  for (size_t k = 0; k < room.outline.size(); ++k) {
    const Vec2 a = room.outline[k], b = room.outline[(k + 1) % room.outline.size()];
    const double len = glm::length(b - a);
    if (len > 0.0 &&
        in_plane(Vec3(a.x, a.y, 0.0), Vec3(-(b.y - a.y) / len, (b.x - a.x) / len, 0.0)))
      return true;
  }
  return false;
}

bool inside_obstacle(const Room& room, const Vec3& p) {
  for (const auto& o : room.obstacles)
    if (p.z > o.z0 && p.z < o.z1 &&
        geometry::locate(Vec2(p.x, p.y), o.footprint, 0.0) == geometry::Location::inside)
      return true;
  return false;
}

// Cells of the convex polygon `poly` (area fraction `inv_area` x area each) of size at most
// `max_cell_m`: one cell when it is that small, else the fan from its centroid with each
// triangle split into n x n similar triangles (the subdivision of the near field's ladder,
// calc/nearfield/ladder.cpp), each a cell at its centroid.
void add_cells(const Polygon3& poly, double max_cell_m, double inv_area, const Room& room,
               std::vector<EmitterCell>& out) {
  const double area = glm::length(geometry::area_vector(poly));
  if (geometry::polygon_diameter(poly) <= max_cell_m) {
    const Vec3 c = geometry::polygon_centroid(poly);
    if (!inside_obstacle(room, c)) out.push_back({c, area * inv_area});
    return;
  }
  const Vec3 c = geometry::polygon_centroid(poly);
  for (size_t k = 0; k < poly.size(); ++k) {
    const Vec3 b = poly[k], d = poly[(k + 1) % poly.size()];
    const double tri_area = 0.5 * glm::length(glm::cross(b - c, d - c));
    if (!(tri_area > 0.0)) continue;
    const double diameter = std::max({glm::length(b - c), glm::length(d - c), glm::length(d - b)});
    const int n =
        std::clamp(static_cast<int>(std::ceil(diameter / max_cell_m)), 1, kMaxCellsPerSide);
    const Vec3 u = (b - c) / double(n), v = (d - c) / double(n);
    const double w = tri_area / (double(n) * n) * inv_area;
    auto add = [&](double i, double j) {
      const Vec3 p = c + i * u + j * v;
      if (!inside_obstacle(room, p)) out.push_back({p, w});
    };
    for (int j = 0; j < n; ++j)
      for (int i = 0; i + j < n; ++i) {
        add(i + 1.0 / 3.0, j + 1.0 / 3.0);                      // upright triangle
        if (i + j + 2 <= n) add(i + 2.0 / 3.0, j + 2.0 / 3.0);  // inverted triangle
      }
  }
}

// The share of a point emitter's flux sent into each of `rooms` (which all contain it): the
// sphere of directions in bands of equal solid angle (uniform in cos), each direction given to
// the room a point kProbe_m along it lies in. Directions along the shared face, into no room or
// into a room not listed, count for none.
std::vector<double> flux_share_by_room(const Scene& scene, const nearfield::Emitter& e,
                                       const Vec3& position, const std::vector<int>& rooms) {
  constexpr double kProbe_m = 1e-3;
  constexpr int kBands = 180, kSteps = 360;
  std::vector<double> into(rooms.size(), 0.0);
  double total = 0.0;
  for (int b = 0; b < kBands; ++b) {
    const double z = -1.0 + (b + 0.5) * 2.0 / kBands, s = std::sqrt(1.0 - z * z);
    for (int k = 0; k < kSteps; ++k) {
      const double phi = (k + 0.5) * 2.0 * kPi / kSteps;
      const Vec3 d(s * std::cos(phi), s * std::sin(phi), z);
      const double i = e.intensity_towards(d);
      total += i;
      const int r = room_containing(scene, position + d * kProbe_m, 0.0);
      const auto found = std::find(rooms.begin(), rooms.end(), r);
      if (found != rooms.end()) into[static_cast<size_t>(found - rooms.begin())] += i;
    }
  }
  for (double& v : into) v = total > 0.0 ? v / total : 0.0;
  return into;
}

}  // namespace

std::vector<RoomCells> emitter_cells(const Scene& scene, const Luminaire& lum) {
  const nearfield::Emitter e =
      nearfield::make_emitter(lum.opening, lum.pose.position, lum.pose.rotation, lum.distribution);
  std::vector<RoomCells> out;
  if (e.is_point()) {
    const std::vector<int> rooms = rooms_containing(scene, lum.pose.position, 0.0);
    if (rooms.size() == 1) out.push_back({rooms[0], {{lum.pose.position, 1.0}}, 1.0});
    if (rooms.size() > 1) {
      // On a wall (floor, ceiling) rooms share: the point sends its light into each of them.
      // Each room's patches see only the directions into that room, so the cell carries the
      // whole intensity in each; the weight is the share of the flux entering the room.
      const std::vector<double> share = flux_share_by_room(scene, e, lum.pose.position, rooms);
      for (size_t k = 0; k < rooms.size(); ++k)
        out.push_back({rooms[k], {{lum.pose.position, 1.0}}, share[k]});
    }
    return out;
  }
  const double inv_area = 1.0 / e.area_m2;
  for (size_t r = 0; r < scene.rooms.size(); ++r) {
    const Room& room = scene.rooms[r];
    const double top = room.floor_z + room.height;
    const std::vector<Polygon2> pieces = convex_pieces(room);
    if (pieces.empty()) continue;
    std::vector<Polygon3> parts;
    double inside_area = 0.0;
    for (const Polygon2& piece : pieces) {
      Polygon3 part = clip_to_prism(e.vertices, piece, room.floor_z, top);
      if (part.size() < 3 || flush_emitting_out(part, room, e.normal)) continue;
      const double a = glm::length(geometry::area_vector(part));
      if (!(a > kSliverWidths * kOpeningOnFace_m * geometry::polygon_diameter(part))) continue;
      inside_area += a;
      parts.push_back(std::move(part));
    }
    if (parts.empty()) continue;
    RoomCells rc;
    rc.room = static_cast<int>(r);
    const double extent = smallest_extent(room);
    const bool whole = std::abs(inside_area - e.area_m2) <= kOutsideNoteFraction * e.area_m2;
    if (whole && e.largest_dimension_m <= kPointOpeningToRoom * extent) {
      // Wholly inside and small against the room: one point at the centroid (the model of
      // before, at its cost).
      if (!inside_obstacle(room, e.centroid)) rc.cells.push_back({e.centroid, 1.0});
    } else {
      for (const Polygon3& part : parts)
        add_cells(part, kCellToRoom * extent, inv_area, room, rc.cells);
    }
    for (const auto& c : rc.cells) rc.weight += c.weight;
    if (!rc.cells.empty()) out.push_back(std::move(rc));
  }
  return out;
}

std::optional<IndirectNote> outside_note(const Luminaire& lum, const std::vector<RoomCells>& parts,
                                         const Scene& scene, double luminous_flux_lm) {
  double inside = 0.0;
  for (const auto& p : parts) inside += p.weight;
  const double outside = 1.0 - inside;
  if (!(outside > kOutsideNoteFraction) || parts.empty()) return std::nullopt;
  IndirectNote note;
  note.kind = IndirectNote::Kind::opening_outside;
  note.luminaire = lum.label;
  note.fraction = outside;
  note.disk = lum.opening.shape == photometry::LuminousOpening::Shape::disk;
  note.length_m = lum.opening.length;
  note.width_m = lum.opening.width;
  note.entering_lm = inside * luminous_flux_lm;
  note.flux_lm = luminous_flux_lm;
  for (const auto& p : parts) note.rooms_entered.push_back(scene.rooms[p.room].name);
  return note;
}

}  // namespace luxgrid::calc::indirect
