#include "calc/indirect/patches.h"
#include "util/error.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace luxgrid::calc::indirect {

namespace {

// Pieces smaller than this are dropped from boundary cells: they carry no light worth a patch and
// would only add ill-conditioned form factors. 1 mm^2 over a whole room is far below any tolerance.
constexpr double kMinPieceArea_m2 = 1e-6;

void check_room(const Room& room) {
  const std::string where = "room '" + room.name + "'";
  if (room.outline.size() < 3)
    throw InputError(where + ": outline has " + std::to_string(room.outline.size()) +
                                " vertices, indirect light needs a closed polygon of at least 3");
  if (!(room.height > 0.0))
    throw InputError(where + ": height must be > 0 for indirect light");
  const auto check = [&](double r, const char* face) {
    if (!(r >= 0.0 && r <= 1.0))
      throw InputError(where + ": reflectance of the " + face + " is " +
                                  std::to_string(r) + ", expected a number in [0, 1]");
  };
  check(room.reflectance.floor, "floor");
  check(room.reflectance.walls, "walls");
  check(room.reflectance.ceiling, "ceiling");
  if (!(signed_area2(room.outline) > 0.0))
    throw InputError(where + ": outline must be counter-clockwise with non-zero area");
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
      if (p[s] < 0.0) t0 = std::max(t0, t);
      else t1 = std::min(t1, t);
    }
  }
  return t1 - t0 > 1e-12;
}

void add_patch(PatchMesh& mesh, Polygon3 poly, const Vec3& normal, double reflectance, int room,
               FaceKind face, int face_index) {
  Patch p;
  // Orient the polygon counter-clockwise seen from the room side.
  if (glm::dot(area_vector(poly), normal) < 0.0) std::reverse(poly.begin(), poly.end());
  p.polygon = std::move(poly);
  p.normal = normal;
  p.area_m2 = glm::length(area_vector(p.polygon));
  if (p.area_m2 < kMinPieceArea_m2) return;
  p.centroid = polygon_centroid(p.polygon);
  p.diameter_m = polygon_diameter(p.polygon);
  p.reflectance = reflectance;
  p.room = room;
  p.face = face;
  p.face_index = face_index;
  mesh.patches.push_back(std::move(p));
}

// Floor or ceiling of `room` at height z: 2D convex pieces.
std::vector<Polygon2> horizontal_pieces(const Room& room, double size) {
  const auto& outline = room.outline;
  Vec2 lo = outline[0], hi = outline[0];
  for (const auto& v : outline) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  const int nx = std::max(1, static_cast<int>(std::ceil((hi.x - lo.x) / size - 1e-9)));
  const int ny = std::max(1, static_cast<int>(std::ceil((hi.y - lo.y) / size - 1e-9)));
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
        if (point_in_polygon(outline, 0.5 * (c0 + c1))) pieces.push_back(cell);
        continue;
      }
      if (ears.empty()) ears = ear_clip(outline);
      for (const auto& tri : ears) {
        Polygon2 piece = clip_convex(cell, tri);
        if (piece.size() >= 3 && 0.5 * signed_area2(piece) > kMinPieceArea_m2)
          pieces.push_back(std::move(piece));
      }
    }
  }
  return pieces;
}

}  // namespace

double room_surface_area(const Room& room) {
  double perimeter = 0.0;
  for (size_t k = 0; k < room.outline.size(); ++k)
    perimeter += glm::length(room.outline[(k + 1) % room.outline.size()] - room.outline[k]);
  return std::abs(signed_area2(room.outline)) + perimeter * room.height;
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
  for (size_t r = 0; r < scene.rooms.size(); ++r) {
    const Room& room = scene.rooms[r];
    if (p.z < room.floor_z - tolerance_m || p.z > room.floor_z + room.height + tolerance_m) continue;
    const Vec2 q(p.x, p.y);
    if (point_in_polygon(room.outline, q) || distance_to_boundary(room.outline, q) <= tolerance_m)
      return static_cast<int>(r);
  }
  return -1;
}

PatchMesh build_patch_mesh(const Scene& scene, double patch_size_m) {
  if (!(patch_size_m > 0.0)) throw InputError("indirect: patch size must be > 0");
  PatchMesh mesh;
  mesh.patch_size_m = patch_size_m;
  for (size_t r = 0; r < scene.rooms.size(); ++r) {
    const Room& room = scene.rooms[r];
    check_room(room);
    mesh.room_begin.push_back(mesh.patches.size());
    const int ri = static_cast<int>(r);
    const double z0 = room.floor_z, z1 = room.floor_z + room.height;
    for (const auto& piece : horizontal_pieces(room, patch_size_m)) {
      Polygon3 floor, ceiling;
      for (const auto& v : piece) {
        floor.emplace_back(v.x, v.y, z0);
        ceiling.emplace_back(v.x, v.y, z1);
      }
      add_patch(mesh, std::move(floor), Vec3(0, 0, 1), room.reflectance.floor, ri,
                FaceKind::floor, 0);
      add_patch(mesh, std::move(ceiling), Vec3(0, 0, -1), room.reflectance.ceiling, ri,
                FaceKind::ceiling, 0);
    }
    const auto& o = room.outline;
    const int nv = std::max(1, static_cast<int>(std::ceil(room.height / patch_size_m - 1e-9)));
    for (size_t k = 0; k < o.size(); ++k) {
      const Vec2 a = o[k], b = o[(k + 1) % o.size()];
      const double len = glm::length(b - a);
      if (!(len > 0.0)) continue;
      const Vec2 t = (b - a) / len;
      const Vec3 inward(-t.y, t.x, 0.0);  // counter-clockwise outline: the room is on the left
      const int nu = std::max(1, static_cast<int>(std::ceil(len / patch_size_m - 1e-9)));
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
  return mesh;
}

}  // namespace luxgrid::calc::indirect
