#include "calc/indirect/patches.h"

#include "calc/indirect/form_factor.h"
#include "calc/opening_placement.h"
#include "calc/scene_visibility.h"
#include "geometry/narrowed_visibility.h"
#include "util/error.h"
#include "util/robust_math.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <stdexcept>

namespace luxgrid::calc::indirect {

namespace {

// Pieces smaller than this are dropped from boundary cells: they carry no light worth a patch and
// would only add ill-conditioned form factors. 1 mm^2 over a whole room is far below any tolerance.
constexpr double kMinPieceArea_m2 = 1e-6;
// An obstacle whose bottom is within this distance of the floor stands on it (its footprint is cut
// out of the floor and its bottom face is dropped: the two would face each other at zero distance,
// both dark, and a floor patch half under the obstacle would shoot its light from a centroid
// inside the obstacle, where every ray is blocked, and lose it). Likewise at the ceiling.
constexpr double kTouch_m = 1e-4;

void check_room(const Room& room) {
  const std::string where = "room '" + room.name + "'";
  if (room.outline.size() < 3)
    throw InputError(where + ": outline has " + std::to_string(room.outline.size()) +
                     " vertices, indirect light needs a closed polygon of at least 3");
  if (!(room.height > 0.0)) throw InputError(where + ": height must be > 0 for indirect light");
  const auto check = [&](double r, const char* face) {
    if (!(r >= 0.0 && r <= 1.0))
      throw InputError(where + ": reflectance of the " + face + " is " + std::to_string(r) +
                       ", expected a number in [0, 1]");
  };
  check(room.reflectance.floor, "floor");
  check(room.reflectance.walls, "walls");
  check(room.reflectance.ceiling, "ceiling");
  // A self-crossing outline has no inside: the faces would not close, and light would leak.
  const auto& o = room.outline;
  const size_t n = o.size();
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours (wrapping)
      if (geometry::segments_cross(o[i], o[(i + 1) % n], o[j], o[(j + 1) % n]))
        throw InputError(where + ": outline edges " + std::to_string(i) + " and " +
                         std::to_string(j) + " cross, so the room is not closed (it leaks); " +
                         "indirect light needs a simple outline");
    }
  if (!(geometry::signed_area(room.outline) > 0.0))
    throw InputError(where + ": outline must be counter-clockwise with non-zero area");
  for (const auto& ob : room.obstacles) {
    if (!(ob.reflectance >= 0.0 && ob.reflectance <= 1.0))
      throw InputError(where + ", obstacle '" + ob.name + "': reflectance is " +
                       std::to_string(ob.reflectance) + ", expected a number in [0, 1]");
    if (ob.footprint.size() < 3 || !(geometry::signed_area(ob.footprint) > 0.0))
      throw InputError(where + ", obstacle '" + ob.name +
                       "': footprint must be a counter-clockwise polygon with non-zero area");
  }
}

// `poly` (convex) clipped to the left (keep_left) or right of the line a -> b.
Polygon2 clip_half_plane(const Polygon2& poly, const Vec2& a, const Vec2& b, bool keep_left) {
  Polygon2 out;
  const auto side = [&](const Vec2& p) {
    const double o = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    return keep_left ? o : -o;
  };
  for (size_t k = 0, m = poly.size(); k < m; ++k) {
    const Vec2 p = poly[k], q = poly[(k + 1) % m];
    const double dp = side(p), dq = side(q);
    if (dp >= 0.0) out.push_back(p);
    if ((dp >= 0.0) != (dq >= 0.0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
  }
  return out;
}

// Convex `piece` minus the convex counter-clockwise `hole`: up to one convex piece per hole edge
// (the part outside that edge and inside the previous ones); the part inside the hole is dropped.
void subtract_convex(const Polygon2& piece, const Polygon2& hole, std::vector<Polygon2>& out) {
  Polygon2 rest = piece;
  for (size_t k = 0, n = hole.size(); k < n && rest.size() >= 3; ++k) {
    const Vec2 a = hole[k], b = hole[(k + 1) % n];
    Polygon2 outside = clip_half_plane(rest, a, b, false);
    if (outside.size() >= 3 && std::abs(geometry::signed_area(outside)) > kMinPieceArea_m2)
      out.push_back(std::move(outside));
    rest = clip_half_plane(rest, a, b, true);
  }
}

// Pieces minus every convex hole (holes may overlap: each is subtracted in turn).
std::vector<Polygon2> subtract_holes(std::vector<Polygon2> pieces,
                                     const std::vector<Polygon2>& holes) {
  for (const auto& hole : holes) {
    Vec2 hlo = hole[0], hhi = hole[0];
    for (const auto& v : hole) hlo = glm::min(hlo, v), hhi = glm::max(hhi, v);
    std::vector<Polygon2> next;
    for (auto& p : pieces) {
      Vec2 lo = p[0], hi = p[0];
      for (const auto& v : p) lo = glm::min(lo, v), hi = glm::max(hi, v);
      if (hi.x <= hlo.x || lo.x >= hhi.x || hi.y <= hlo.y || lo.y >= hhi.y) {
        next.push_back(std::move(p));
        continue;
      }
      subtract_convex(p, hole, next);
    }
    pieces.swap(next);
  }
  return pieces;
}

// True when the open segment ab enters the open axis-aligned box [lo, hi] (Liang-Barsky).
bool segment_enters_box(const Vec2& a, const Vec2& b, const Vec2& lo, const Vec2& hi) {
  double t0 = 0.0, t1 = 1.0;
  const Vec2 d = b - a;
  for (int k = 0; k < 2; ++k) {
    const double p[2] = {-d[k], d[k]};
    const double q[2] = {a[k] - lo[k], hi[k] - a[k]};
    for (int s = 0; s < 2; ++s) {
      if (p[s] == 0.0) {
        if (q[s] <= 0.0) return false;
        continue;
      }
      const double t = q[s] / p[s];
      if (p[s] < 0.0)
        t0 = std::max(t0, t);
      else
        t1 = std::min(t1, t);
    }
  }
  return t1 - t0 > 1e-12;
}

// Each patch's form factor to the openings of its room (PatchMesh::escape_fraction), when the
// scene has openings.
void set_escape_fractions(const Scene& scene, PatchMesh& mesh) {
  if (scene.openings.empty()) return;
  mesh.escape_fraction.assign(mesh.patches.size(), 0.0);
  for (size_t i = 0; i < mesh.patches.size(); ++i) {
    const Patch& p = mesh.patches[i];
    for (const DaylightOpening& o : scene.openings)
      if (o.room == static_cast<size_t>(p.room))
        mesh.escape_fraction[i] += point_polygon_form_factor(p.centroid, p.normal, o.polygon);
    mesh.escape_fraction[i] = std::min(mesh.escape_fraction[i], 1.0);
  }
}

void add_patch(PatchMesh& mesh, Polygon3 poly, const Vec3& normal, double reflectance, int room,
               FaceKind face, int face_index) {
  Patch p;
  // Orient the polygon counter-clockwise seen from the room side.
  if (glm::dot(geometry::area_vector(poly), normal) < 0.0) std::reverse(poly.begin(), poly.end());
  p.polygon = std::move(poly);
  p.normal = normal;
  p.area_m2 = glm::length(geometry::area_vector(p.polygon));
  if (p.area_m2 < kMinPieceArea_m2) return;
  p.centroid = geometry::polygon_centroid(p.polygon);
  p.diameter_m = geometry::polygon_diameter(p.polygon);
  if (p.polygon.size() == 4) {
    // A parallelogram when the diagonals bisect each other; its quarters' centroids are then
    // halfway between the centre and each corner.
    const Vec3 mid02 = 0.5 * (p.polygon[0] + p.polygon[2]),
               mid13 = 0.5 * (p.polygon[1] + p.polygon[3]);
    if (glm::length(mid02 - mid13) <= 1e-9 * p.diameter_m) {
      p.has_quarters = true;
      for (int k = 0; k < 4; ++k) p.quarter_centroid[k] = 0.5 * (p.polygon[k] + p.centroid);
    }
  }
  p.reflectance = reflectance;
  p.room = room;
  p.face = face;
  p.face_index = face_index;
  mesh.patches.push_back(std::move(p));
}

// A horizontal face (floor, ceiling, obstacle top or bottom) with the given outline: 2D convex
// pieces, cells of about `size`.
std::vector<Polygon2> horizontal_pieces(const Polygon2& outline, double size) {
  Vec2 lo = outline[0], hi = outline[0];
  for (const auto& v : outline) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  const int nx = pieces_of_at_most((hi.x - lo.x) / size);
  const int ny = pieces_of_at_most((hi.y - lo.y) / size);
  const double dx = (hi.x - lo.x) / nx, dy = (hi.y - lo.y) / ny;
  std::vector<Polygon2> ears;  // built only if a boundary cell needs it
  std::vector<Polygon2> pieces;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const Vec2 c0(lo.x + i * dx, lo.y + j * dy), c1(lo.x + (i + 1) * dx, lo.y + (j + 1) * dy);
      const Polygon2 cell = {c0, {c1.x, c0.y}, c1, {c0.x, c1.y}};
      bool crossed = false;
      for (size_t k = 0; k < outline.size() && !crossed; ++k)
        crossed = segment_enters_box(outline[k], outline[(k + 1) % outline.size()], c0, c1);
      if (!crossed) {
        // No outline edge enters the cell: it is wholly inside or wholly outside.
        if (geometry::locate(0.5 * (c0 + c1), outline) != geometry::Location::outside)
          pieces.push_back(cell);
        continue;
      }
      if (ears.empty()) ears = geometry::triangles(outline);
      for (const auto& tri : ears) {
        Polygon2 piece = geometry::clip_convex(cell, tri);
        if (piece.size() >= 3 && geometry::signed_area(piece) > kMinPieceArea_m2)
          pieces.push_back(std::move(piece));
      }
    }
  }
  return pieces;
}

// The openings of room `r` in one face, as convex counter-clockwise triangles in the face's 2D
// coordinates (opening_placement.h: x, y for floor and ceiling; along the wall and z for a wall).
std::vector<Polygon2> opening_holes(const Scene& scene, size_t r, RoomFaceRef::Kind kind,
                                    size_t wall) {
  std::vector<Polygon2> holes;
  for (const DaylightOpening& o : scene.openings) {
    if (o.room != r || o.face.kind != kind) continue;
    if (kind == RoomFaceRef::Kind::wall && o.face.wall != wall) continue;
    Polygon2 flat = face_coordinates(scene.rooms[r], o.face, o.polygon);
    if (geometry::signed_area(flat) < 0.0) std::reverse(flat.begin(), flat.end());
    for (auto& t : geometry::triangles(flat)) holes.push_back(std::move(t));
  }
  return holes;
}

}  // namespace

double room_surface_area(const Room& room) {
  return 2.0 * std::abs(geometry::signed_area(room.outline)) +
         geometry::perimeter(room.outline) * room.height;
}

bool outline_is_convex(const Room& room) {
  const auto& o = room.outline;
  for (size_t k = 0, n = o.size(); k < n; ++k) {
    const Vec2 a = o[k], b = o[(k + 1) % n], c = o[(k + 2) % n];
    const Vec2 ab = b - a, bc = c - b;
    if (ab.x * bc.y - ab.y * bc.x < -1e-12) return false;
  }
  return true;
}

int room_containing(const Scene& scene, const Vec3& p, double tolerance_m) {
  for (size_t r = 0; r < scene.rooms.size(); ++r)
    if (inside_room(scene.rooms[r], p, tolerance_m)) return static_cast<int>(r);
  return -1;
}

std::vector<int> rooms_containing(const Scene& scene, const Vec3& p, double tolerance_m) {
  std::vector<int> out;
  for (size_t r = 0; r < scene.rooms.size(); ++r)
    if (inside_room(scene.rooms[r], p, tolerance_m)) out.push_back(static_cast<int>(r));
  return out;
}

PatchMesh build_patch_mesh(const Scene& scene, double patch_size_m) {
  if (!(patch_size_m > 0.0)) throw InputError("indirect: patch size must be > 0");
  PatchMesh mesh;
  mesh.patch_size_m = patch_size_m;
  {
    // Room for the patches up front (a few thousand structs with their polygons: growing the
    // vector step by step moved them about a dozen times).
    double estimate = 0.0;
    for (const Room& room : scene.rooms) {
      if (room.outline.empty()) continue;
      Vec2 lo = room.outline[0], hi = room.outline[0];
      for (const auto& v : room.outline) lo = glm::min(lo, v), hi = glm::max(hi, v);
      const double cells = (std::ceil((hi.x - lo.x) / patch_size_m) + 1.0) *
                           (std::ceil((hi.y - lo.y) / patch_size_m) + 1.0);
      estimate += 2.0 * cells + 4.0 * room_surface_area(room) / (patch_size_m * patch_size_m) +
                  64.0 * static_cast<double>(room.obstacles.size() + 1);
    }
    if (estimate > 0.0 && estimate < 1e7) mesh.patches.reserve(static_cast<size_t>(estimate));
  }
  for (size_t r = 0; r < scene.rooms.size(); ++r) {
    const Room& room = scene.rooms[r];
    check_room(room);
    mesh.room_begin.push_back(mesh.patches.size());
    const int ri = static_cast<int>(r);
    const double z0 = room.floor_z, z1 = room.floor_z + room.height;
    // Footprints (as convex triangles) of obstacles standing on the floor / touching the ceiling.
    std::vector<Polygon2> floor_holes = opening_holes(scene, r, RoomFaceRef::Kind::floor, 0);
    std::vector<Polygon2> ceiling_holes = opening_holes(scene, r, RoomFaceRef::Kind::ceiling, 0);
    for (const auto& ob : room.obstacles) {
      if (ob.z0 <= z0 + kTouch_m)
        for (auto& t : geometry::triangles(ob.footprint)) floor_holes.push_back(t);
      if (ob.z1 >= z1 - kTouch_m)
        for (auto& t : geometry::triangles(ob.footprint)) ceiling_holes.push_back(t);
    }
    const std::vector<Polygon2> pieces = horizontal_pieces(room.outline, patch_size_m);
    for (const auto& piece : floor_holes.empty() ? pieces : subtract_holes(pieces, floor_holes)) {
      Polygon3 floor;
      for (const auto& v : piece) floor.emplace_back(v.x, v.y, z0);
      add_patch(mesh, std::move(floor), Vec3(0, 0, 1), room.reflectance.floor, ri, FaceKind::floor,
                0);
    }
    for (const auto& piece :
         ceiling_holes.empty() ? pieces : subtract_holes(pieces, ceiling_holes)) {
      Polygon3 ceiling;
      for (const auto& v : piece) ceiling.emplace_back(v.x, v.y, z1);
      add_patch(mesh, std::move(ceiling), Vec3(0, 0, -1), room.reflectance.ceiling, ri,
                FaceKind::ceiling, 0);
    }
    // Obstacles: clamped to the room's height; sides outward, top and bottom where exposed.
    for (size_t k = 0; k < room.obstacles.size(); ++k) {
      const auto& ob = room.obstacles[k];
      const int ki = static_cast<int>(k);
      const double b = std::max(ob.z0, z0), t = std::min(ob.z1, z1);
      if (!(t > b)) continue;
      if (t < z1 - kTouch_m || b > z0 + kTouch_m) {
        for (const auto& piece : horizontal_pieces(ob.footprint, patch_size_m)) {
          if (t < z1 - kTouch_m) {
            Polygon3 top;
            for (const auto& v : piece) top.emplace_back(v.x, v.y, t);
            add_patch(mesh, std::move(top), Vec3(0, 0, 1), ob.reflectance, ri, FaceKind::obstacle,
                      ki);
          }
          if (b > z0 + kTouch_m) {
            Polygon3 bottom;
            for (const auto& v : piece) bottom.emplace_back(v.x, v.y, b);
            add_patch(mesh, std::move(bottom), Vec3(0, 0, -1), ob.reflectance, ri,
                      FaceKind::obstacle, ki);
          }
        }
      }
      const auto& f = ob.footprint;
      const int nv = pieces_of_at_most((t - b) / patch_size_m);
      for (size_t e = 0; e < f.size(); ++e) {
        const Vec2 a = f[e], c = f[(e + 1) % f.size()];
        const double len = glm::length(c - a);
        if (!(len > 0.0)) continue;
        const Vec2 dir = (c - a) / len;
        const Vec3 outward(dir.y, -dir.x,
                           0.0);  // counter-clockwise footprint: outside on the right
        const int nu = pieces_of_at_most(len / patch_size_m);
        for (int j = 0; j < nv; ++j) {
          const double za = b + (t - b) * j / nv, zb = b + (t - b) * (j + 1) / nv;
          for (int i = 0; i < nu; ++i) {
            const Vec2 p = a + (c - a) * (static_cast<double>(i) / nu);
            const Vec2 q = a + (c - a) * (static_cast<double>(i + 1) / nu);
            add_patch(mesh, {{p.x, p.y, za}, {q.x, q.y, za}, {q.x, q.y, zb}, {p.x, p.y, zb}},
                      outward, ob.reflectance, ri, FaceKind::obstacle, ki);
          }
        }
      }
    }
    const auto& o = room.outline;
    const int nv = pieces_of_at_most(room.height / patch_size_m);
    for (size_t k = 0; k < o.size(); ++k) {
      const Vec2 a = o[k], b = o[(k + 1) % o.size()];
      const double len = glm::length(b - a);
      if (!(len > 0.0)) continue;
      const Vec2 t = (b - a) / len;
      const Vec3 inward(-t.y, t.x, 0.0);  // counter-clockwise outline: the room is on the left
      const int nu = pieces_of_at_most(len / patch_size_m);
      const std::vector<Polygon2> holes = opening_holes(scene, r, RoomFaceRef::Kind::wall, k);
      if (!holes.empty()) {
        // The wall's rectangles in its (along, z) coordinates, minus its openings, back in 3D.
        std::vector<Polygon2> cells;
        for (int j = 0; j < nv; ++j) {
          const double za = z0 + room.height * j / nv, zb = z0 + room.height * (j + 1) / nv;
          for (int i = 0; i < nu; ++i) {
            const double sa = len * i / nu, sb = len * (i + 1) / nu;
            cells.push_back({{sa, za}, {sb, za}, {sb, zb}, {sa, zb}});
          }
        }
        for (const auto& piece : subtract_holes(std::move(cells), holes)) {
          Polygon3 wall;
          for (const auto& v : piece) wall.emplace_back(a.x + t.x * v.x, a.y + t.y * v.x, v.y);
          add_patch(mesh, std::move(wall), inward, room.reflectance.walls, ri, FaceKind::wall,
                    static_cast<int>(k));
        }
        continue;
      }
      for (int j = 0; j < nv; ++j) {
        const double za = z0 + room.height * j / nv, zb = z0 + room.height * (j + 1) / nv;
        for (int i = 0; i < nu; ++i) {
          const Vec2 p = a + (b - a) * (static_cast<double>(i) / nu);
          const Vec2 q = a + (b - a) * (static_cast<double>(i + 1) / nu);
          add_patch(mesh, {{p.x, p.y, za}, {q.x, q.y, za}, {q.x, q.y, zb}, {p.x, p.y, zb}}, inward,
                    room.reflectance.walls, ri, FaceKind::wall, static_cast<int>(k));
        }
      }
    }
  }
  mesh.room_begin.push_back(mesh.patches.size());
  set_escape_fractions(scene, mesh);
  return mesh;
}

PatchMesh split_patches(const Scene& scene, const PatchMesh& mesh, const std::vector<char>& split) {
  PatchMesh out;
  out.patch_size_m = mesh.patch_size_m;
  out.room_begin.push_back(0);
  for (size_t r = 0; r + 1 < mesh.room_begin.size(); ++r) {
    for (size_t i = mesh.room_begin[r]; i < mesh.room_begin[r + 1]; ++i) {
      const Patch& p = mesh.patches[i];
      if (!split[i] || !p.has_quarters) {
        out.patches.push_back(p);
        continue;
      }
      // Corners and edge midpoints of the parallelogram, each quarter counter-clockwise like it.
      const Polygon3& q = p.polygon;
      const Vec3 m01 = 0.5 * (q[0] + q[1]), m12 = 0.5 * (q[1] + q[2]), m23 = 0.5 * (q[2] + q[3]),
                 m30 = 0.5 * (q[3] + q[0]), c = p.centroid;
      for (const Polygon3& quarter : {Polygon3{q[0], m01, c, m30}, Polygon3{m01, q[1], m12, c},
                                      Polygon3{c, m12, q[2], m23}, Polygon3{m30, c, m23, q[3]}})
        add_patch(out, quarter, p.normal, p.reflectance, p.room, p.face, p.face_index);
    }
    out.room_begin.push_back(out.patches.size());
  }
  set_escape_fractions(scene, out);
  return out;
}

double visible_fraction(const geometry::Visibility* visibility, const Vec3& from,
                        const Patch& target, double lift_m) {
  if (!visibility) return 1.0;
  const Vec3 lift = target.normal * lift_m;
  // The centroid and the midpoints towards the corners, asked together (one coherent stream).
  constexpr size_t kMax = geometry::Visibility::kMaxSegmentsFrom;
  std::array<Vec3, kMax> to;
  std::array<bool, kMax> seen_each;
  const size_t count = std::min(target.polygon.size() + 1, kMax);
  to[0] = target.centroid + lift;
  for (size_t k = 1; k < count; ++k) to[k] = 0.5 * (target.polygon[k - 1] + target.centroid) + lift;
  visibility->visible_from(from, std::span<const Vec3>(to.data(), count), seen_each.data());
  int seen = 0;
  for (size_t k = 0; k < count; ++k) seen += seen_each[k] ? 1 : 0;
  for (size_t k = count; k <= target.polygon.size(); ++k)
    if (visibility->visible(from, 0.5 * (target.polygon[k - 1] + target.centroid) + lift)) ++seen;
  return static_cast<double>(seen) / static_cast<double>(target.polygon.size() + 1);
}

double visible_fraction_within(const geometry::Visibility* visibility, const Vec3& from,
                               const Patch& target, double lift_m,
                               const geometry::ShaftFaces& among) {
  if (!visibility || !among.narrowed()) return visible_fraction(visibility, from, target, lift_m);
  const geometry::NarrowedVisibility narrowed(*visibility, among);
  return visible_fraction(&narrowed, from, target, lift_m);
}

}  // namespace luxgrid::calc::indirect
