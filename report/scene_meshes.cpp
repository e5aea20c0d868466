#include "report/scene_meshes.h"

#include <algorithm>
#include <cmath>

#include "calc/opening_placement.h"
#include "geometry/polygon.h"
#include "geometry/polygon_with_holes.h"

namespace luxgrid::report {

namespace {

using gltf::Primitive;

std::uint32_t vertex(Primitive& p, const Vec3& v) {
  p.positions.push_back(static_cast<float>(v.x));
  p.positions.push_back(static_cast<float>(v.y));
  p.positions.push_back(static_cast<float>(v.z));
  return static_cast<std::uint32_t>(p.positions.size() / 3 - 1);
}
void triangle(Primitive& p, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  p.indices.insert(p.indices.end(), {a, b, c});
}
// A planar quadrilateral a b c d, counter-clockwise seen from the side it shows.
void quad(Primitive& p, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const std::uint32_t i = vertex(p, a), j = vertex(p, b), k = vertex(p, c), l = vertex(p, d);
  triangle(p, i, j, k);
  triangle(p, i, k, l);
}
// Triangles over the vertices from `first` on, counter-clockwise as given, or turned.
void triangles_from(Primitive& p, std::uint32_t first,
                    const std::vector<std::array<int, 3>>& triangles, bool turn) {
  for (const auto& t : triangles) {
    const auto a = first + static_cast<std::uint32_t>(t[0]);
    const auto b = first + static_cast<std::uint32_t>(t[1]);
    const auto c = first + static_cast<std::uint32_t>(t[2]);
    if (turn)
      triangle(p, a, c, b);
    else
      triangle(p, a, b, c);
  }
}
// The polygon `ccw` (seen from above) at height z, facing up or down.
void cap(Primitive& p, const std::vector<Vec2>& ccw, double z, bool up) {
  const std::uint32_t first = static_cast<std::uint32_t>(p.positions.size() / 3);
  for (const Vec2& c : ccw) vertex(p, Vec3(c.x, c.y, z));
  triangles_from(p, first, geometry::triangulate(ccw), !up);
}
// The sides between z0 and z1 along the counter-clockwise outline: facing out, or in.
void sides(Primitive& p, const std::vector<Vec2>& ccw, double z0, double z1, bool out) {
  for (std::size_t i = 0; i < ccw.size(); ++i) {
    const Vec2 a = ccw[i], b = ccw[(i + 1) % ccw.size()];
    if (out)
      quad(p, Vec3(a.x, a.y, z0), Vec3(b.x, b.y, z0), Vec3(b.x, b.y, z1), Vec3(a.x, a.y, z1));
    else
      quad(p, Vec3(b.x, b.y, z0), Vec3(a.x, a.y, z0), Vec3(a.x, a.y, z1), Vec3(b.x, b.y, z1));
  }
}

// The opening's outline seen from above, counter-clockwise, at least `min_size` across: a
// rectangle, or an ellipse (a disk) of 48 chords.
std::vector<Vec2> outline(const photometry::LuminousOpening& o, double min_size) {
  using Shape = photometry::LuminousOpening::Shape;
  const bool point = o.shape == Shape::point;
  const double l = std::max(point ? kPointOpeningDiameter : o.length, min_size);
  const double w = std::max(point ? kPointOpeningDiameter : o.width, min_size);
  if (o.shape == Shape::rectangle)
    return {{-l / 2, -w / 2}, {l / 2, -w / 2}, {l / 2, w / 2}, {-l / 2, w / 2}};
  std::vector<Vec2> out;
  constexpr int kChords = 48;
  for (int k = 0; k < kChords; ++k) {
    const double a = 2.0 * kPi * k / kChords;
    out.push_back({l / 2 * std::cos(a), w / 2 * std::sin(a)});
  }
  return out;
}

}  // namespace

namespace {

using FaceKind = calc::RoomFaceRef::Kind;

// A face of `room` in its own 2D coordinates (calc::face_coordinates: x, y for the floor and the
// ceiling; along the wall from its first corner, and z, for a wall), counter-clockwise.
std::vector<Vec2> face_outline_2d(const calc::Room& room, const calc::RoomFaceRef& face) {
  if (face.kind != FaceKind::wall) return room.outline;
  const Vec2 a = room.outline[face.wall], b = room.outline[(face.wall + 1) % room.outline.size()];
  const double length = glm::length(b - a), z0 = room.floor_z, z1 = room.floor_z + room.height;
  return {{0.0, z0}, {length, z0}, {length, z1}, {0.0, z1}};
}
// A point of the face's 2D coordinates in the room.
Vec3 face_point(const calc::Room& room, const calc::RoomFaceRef& face, const Vec2& q) {
  if (face.kind == FaceKind::floor) return {q.x, q.y, room.floor_z};
  if (face.kind == FaceKind::ceiling) return {q.x, q.y, room.floor_z + room.height};
  const Vec2 a = room.outline[face.wall], b = room.outline[(face.wall + 1) % room.outline.size()];
  const Vec2 on = a + (b - a) * (q.x / glm::length(b - a));
  return {on.x, on.y, q.y};
}
// The face less the openings in it, facing into the room: the floor's counter-clockwise
// triangles (seen from above) face up already; the ceiling's and a wall's (counter-clockwise
// along the wall and up, so facing out) are turned.
void holed_face(Primitive& p, const calc::Room& room, const calc::RoomFaceRef& face,
                const std::vector<const calc::DaylightOpening*>& in_face) {
  std::vector<geometry::Polygon2> holes;
  for (const calc::DaylightOpening* o : in_face)
    holes.push_back(calc::face_coordinates(room, face, o->polygon));
  const geometry::HoledTriangulation t =
      geometry::triangulate_with_holes(face_outline_2d(room, face), holes);
  const std::uint32_t first = static_cast<std::uint32_t>(p.positions.size() / 3);
  for (const Vec2& q : t.vertices) vertex(p, face_point(room, face, q));
  triangles_from(p, first, t.triangles, face.kind != FaceKind::floor);
}
// The openings lying in `face`.
std::vector<const calc::DaylightOpening*> openings_in(
    const std::vector<calc::DaylightOpening>& openings, const calc::RoomFaceRef& face) {
  std::vector<const calc::DaylightOpening*> out;
  for (const auto& o : openings)
    if (o.face.kind == face.kind && (face.kind != FaceKind::wall || o.face.wall == face.wall))
      out.push_back(&o);
  return out;
}

}  // namespace

std::vector<Primitive> room_primitives(const calc::Room& room,
                                       const std::vector<calc::DaylightOpening>& openings) {
  const double z0 = room.floor_z, z1 = room.floor_z + room.height;
  std::vector<Primitive> out(3);
  const auto floor = openings_in(openings, {FaceKind::floor, 0});
  if (floor.empty())
    cap(out[0], room.outline, z0, true);
  else
    holed_face(out[0], room, {FaceKind::floor, 0}, floor);
  for (std::size_t k = 0; k < room.outline.size(); ++k) {
    const auto wall = openings_in(openings, {FaceKind::wall, k});
    if (wall.empty()) {
      const Vec2 a = room.outline[k], b = room.outline[(k + 1) % room.outline.size()];
      quad(out[1], Vec3(b.x, b.y, z0), Vec3(a.x, a.y, z0), Vec3(a.x, a.y, z1), Vec3(b.x, b.y, z1));
    } else {
      holed_face(out[1], room, {FaceKind::wall, k}, wall);
    }
  }
  const auto ceiling = openings_in(openings, {FaceKind::ceiling, 0});
  if (ceiling.empty())
    cap(out[2], room.outline, z1, false);
  else
    holed_face(out[2], room, {FaceKind::ceiling, 0}, ceiling);
  return out;
}

Primitive daylight_pane_primitive(const calc::Room& room, const calc::DaylightOpening& o) {
  Primitive p;
  geometry::Polygon2 flat = calc::face_coordinates(room, o.face, o.polygon);
  const bool reversed = geometry::signed_area(flat) < 0.0;
  if (reversed) std::reverse(flat.begin(), flat.end());
  for (const Vec3& c : o.polygon) vertex(p, c);
  const auto n = static_cast<std::uint32_t>(o.polygon.size());
  for (const auto& t : geometry::triangulate_with_holes(flat, {}).triangles) {
    std::array<std::uint32_t, 3> i;
    for (int k = 0; k < 3; ++k)
      i[k] = reversed ? n - 1 - static_cast<std::uint32_t>(t[k]) : static_cast<std::uint32_t>(t[k]);
    triangle(p, i[0], i[1], i[2]);
  }
  return p;
}

Primitive daylight_outline_primitive(const calc::DaylightOpening& o) {
  Primitive p;
  p.mode = gltf::Mode::line_loop;
  for (const Vec3& c : o.polygon) p.indices.push_back(vertex(p, c));
  return p;
}

Primitive prism_primitive(const geometry::Obstacle& o) {
  Primitive p;
  cap(p, o.footprint, o.z1, true);
  cap(p, o.footprint, o.z0, false);
  sides(p, o.footprint, o.z0, o.z1, true);
  return p;
}

Primitive opening_primitive(const photometry::LuminousOpening& o) {
  Primitive p;
  cap(p, outline(o, 0.0), 0.0, false);
  return p;
}

Primitive body_primitive(const photometry::LuminousOpening& o) {
  // At least 5 cm across, so that a small opening's body is seen.
  const std::vector<Vec2> f = outline(o, 0.05);
  Primitive p;
  cap(p, f, kBodyHeight, true);
  sides(p, f, 0.0, kBodyHeight, true);
  return p;
}

Primitive c0_arrow_primitive(const photometry::LuminousOpening& o) {
  const std::vector<Vec2> f = outline(o, kPointOpeningDiameter);
  double reach = 0.0;  // how far the opening reaches along +x
  for (const Vec2& c : f) reach = std::max(reach, c.x);
  const double tip = reach + 0.15, half_width = 0.03, z = -0.002;
  // Seen from below (the side it faces): from the centre to beyond the opening's edge.
  const std::vector<Vec2> arrow = {{0.0, -half_width / 2},    {tip - 0.06, -half_width / 2},
                                   {tip - 0.06, -half_width}, {tip, 0.0},
                                   {tip - 0.06, half_width},  {tip - 0.06, half_width / 2},
                                   {0.0, half_width / 2}};
  Primitive p;
  cap(p, arrow, z, false);
  return p;
}

Primitive marker_primitive(double r) {
  Primitive p;
  const Vec3 v[6] = {{r, 0, 0}, {-r, 0, 0}, {0, r, 0}, {0, -r, 0}, {0, 0, r}, {0, 0, -r}};
  for (const Vec3& c : v) vertex(p, c);
  // The eight faces, each counter-clockwise seen from outside.
  const std::uint32_t f[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                 {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (const auto& t : f) triangle(p, t[0], t[1], t[2]);
  return p;
}

Primitive solid_primitive(const PhotometricSolid& solid, double m_per_cd) {
  Primitive p;
  for (int c = 0; c < kSolidCPlanes; ++c)
    for (int g = 0; g < kSolidGammas; ++g)
      vertex(p, solid_direction(c, g) * (solid.cd[c * kSolidGammas + g] * m_per_cd));
  // Between neighbouring C planes (the last next to the first) and angles; drawn from both
  // sides, so the winding does not matter. Triangles of zero area (the poles, or where the
  // intensity is zero) are left out.
  const auto at = [](int c, int g) {
    return static_cast<std::uint32_t>((c % kSolidCPlanes) * kSolidGammas + g);
  };
  const auto area_of = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const float* v = p.positions.data();
    const Vec3 A(v[3 * a], v[3 * a + 1], v[3 * a + 2]), B(v[3 * b], v[3 * b + 1], v[3 * b + 2]),
        C(v[3 * c], v[3 * c + 1], v[3 * c + 2]);
    return glm::length(glm::cross(B - A, C - A));
  };
  for (int c = 0; c < kSolidCPlanes; ++c)
    for (int g = 0; g + 1 < kSolidGammas; ++g) {
      const std::uint32_t a = at(c, g), b = at(c + 1, g), d = at(c + 1, g + 1), e = at(c, g + 1);
      if (area_of(a, b, d) > 1e-12) triangle(p, a, b, d);
      if (area_of(a, d, e) > 1e-12) triangle(p, a, d, e);
    }
  return p;
}

namespace {
// The rows (or columns) a grid of n along one side is drawn with: every `stride`-th and the last.
std::vector<int> drawn_lines(int n) {
  const int stride = (n + kMaxGridSide - 1) / kMaxGridSide;
  std::vector<int> out;
  for (int i = 0; i < n; i += std::max(stride, 1)) out.push_back(i);
  if (n > 0 && out.back() != n - 1) out.push_back(n - 1);
  return out;
}
}  // namespace

Primitive grid_primitive(const geometry::SurfaceGrid& g, std::vector<int>* vertex_of) {
  Primitive p;
  const std::vector<int> us = drawn_lines(g.nu), vs = drawn_lines(g.nv);
  std::vector<int> index(g.points.size(), -1);
  for (int v : vs)
    for (int u : us) {
      const std::size_t i = static_cast<std::size_t>(v) * g.nu + u;
      if (g.active[i])
        index[i] = static_cast<int>(vertex(p, g.points[i] + g.normals[i] * kGridLift));
    }
  // Cells between drawn points (u, v), (u', v), (u', v'), (u, v'), each triangle turned to face
  // the side the grid's normals give (into the room for a room's surfaces), so that a ceiling's
  // grid seen from above is not drawn, like the ceiling.
  const auto at = [&](int u, int v) { return index[static_cast<std::size_t>(v) * g.nu + u]; };
  const Vec3 facing = glm::cross(g.u_dir, g.v_dir);
  bool flip = false;
  for (std::size_t i = 0; i < g.points.size(); ++i)
    if (g.active[i]) {
      flip = glm::dot(facing, g.normals[i]) < 0.0;
      break;
    }
  for (std::size_t kv = 0; kv + 1 < vs.size(); ++kv)
    for (std::size_t ku = 0; ku + 1 < us.size(); ++ku) {
      const int a = at(us[ku], vs[kv]), b = at(us[ku + 1], vs[kv]), c = at(us[ku + 1], vs[kv + 1]),
                d = at(us[ku], vs[kv + 1]);
      const auto put = [&](int x, int y, int z) {
        if (x < 0 || y < 0 || z < 0) return;
        if (flip) std::swap(y, z);
        triangle(p, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y),
                 static_cast<std::uint32_t>(z));
      };
      if (a >= 0 && c >= 0) {
        put(a, b, c);
        put(a, c, d);
      } else {
        put(a, b, d);
        put(b, c, d);
      }
    }
  if (vertex_of) *vertex_of = std::move(index);
  return p;
}

}  // namespace luxgrid::report
