#include "geometry/room.h"

#include <algorithm>
#include <cmath>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "util/error.h"
#include "util/format.h"

namespace luxgrid::geometry {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;

K::Point_2 cgal(const Vec2& p) { return {p.x, p.y}; }

std::string corner_pair(size_t a, size_t b) { return std::to_string(a) + "-" + std::to_string(b); }

// Edges (a, b) and (c, d) of a polygon with exact predicates. Neighbouring edges share a corner
// and may only meet there; others may not meet at all.
bool edges_meet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  return CGAL::do_intersect(K::Segment_2(cgal(a), cgal(b)), K::Segment_2(cgal(c), cgal(d)));
}

// Neighbouring edges a->b, b->c fold back onto each other when c lies on the ray from b to a.
bool folds_back(const Vec2& a, const Vec2& b, const Vec2& c) {
  if (CGAL::orientation(cgal(a), cgal(b), cgal(c)) != CGAL::COLLINEAR) return false;
  return glm::dot(a - b, c - b) > 0.0;
}
}  // namespace

bool normalize_outline(Polygon2& outline, const std::string& object) {
  const size_t n = outline.size();
  if (n < 3) {
    throw InputError(object + ": an outline needs at least 3 corners, got " + std::to_string(n));
  }
  for (size_t i = 0; i < n; ++i) {
    if (!std::isfinite(outline[i].x) || !std::isfinite(outline[i].y)) {
      throw InputError(object + ": corner " + std::to_string(i) + " is not a finite point");
    }
    const size_t j = (i + 1) % n;
    if (outline[i] == outline[j]) {
      throw InputError(object + ": corners " + std::to_string(i) + " and " + std::to_string(j) +
                       " coincide");
    }
  }
  // Zero area: compare with the size of the polygon, so rounding in a huge outline is not
  // mistaken for a real area and a tiny real room is not rejected.
  double extent = 0.0;
  for (const auto& p : outline)
    extent = std::max({extent, std::abs(p.x - outline[0].x), std::abs(p.y - outline[0].y)});
  constexpr double kRelativeAreaFloor = 1e-12;  // of extent^2; below this the outline is a line
  const double area = signed_area(outline);
  const double area_floor = kRelativeAreaFloor * extent * extent;
  // All corners on one line: report the zero area rather than the fold it makes.
  bool collinear = true;
  for (size_t i = 2; i < n && collinear; ++i) {
    collinear =
        CGAL::orientation(cgal(outline[0]), cgal(outline[1]), cgal(outline[i])) == CGAL::COLLINEAR;
  }
  if (collinear) throw InputError(object + ": the outline has zero area");
  for (size_t i = 0; i < n; ++i) {
    const size_t i1 = (i + 1) % n;
    for (size_t j = i + 1; j < n; ++j) {
      const size_t j1 = (j + 1) % n;
      const bool next = j == i1;
      const bool prev = j1 == i;
      bool bad = false;
      if (next)
        bad = folds_back(outline[i], outline[i1], outline[j1]);
      else if (prev)
        bad = folds_back(outline[j], outline[i], outline[i1]);
      else
        bad = edges_meet(outline[i], outline[i1], outline[j], outline[j1]);
      if (bad) {
        throw InputError(object + ": the outline crosses itself (edge " + corner_pair(i, i1) +
                         " meets edge " + corner_pair(j, j1) + ")");
      }
    }
  }
  // Simple but thinner than rounding noise (a sliver): as good as no area.
  if (!(std::abs(area) > area_floor)) throw InputError(object + ": the outline has zero area");
  if (area < 0.0) {
    std::reverse(outline.begin(), outline.end());
    return true;
  }
  return false;
}

Obstacle make_box(const std::string& name, const Vec3& min, const Vec3& max, double rotation_z_rad,
                  double reflectance) {
  const char* axes = "xyz";
  for (int k = 0; k < 3; ++k) {
    if (!(min[k] < max[k])) {
      throw InputError("obstacle \"" + name + "\": box min must be below max in x, y and z, got " +
                       axes[k] + " from " + format_number(min[k]) + " to " + format_number(max[k]));
    }
  }
  Obstacle o;
  o.name = name;
  o.z0 = min.z;
  o.z1 = max.z;
  o.reflectance = reflectance;
  const Vec2 c((min.x + max.x) / 2.0, (min.y + max.y) / 2.0);
  const double cs = std::cos(rotation_z_rad), sn = std::sin(rotation_z_rad);
  const Vec2 corners[4] = {{min.x, min.y}, {max.x, min.y}, {max.x, max.y}, {min.x, max.y}};
  for (const auto& p : corners) {
    if (rotation_z_rad == 0.0) {
      o.footprint.push_back(p);  // exact corners for the common unrotated box
    } else {
      const Vec2 d = p - c;
      o.footprint.push_back(c + Vec2(cs * d.x - sn * d.y, sn * d.x + cs * d.y));
    }
  }
  return o;
}

Obstacle make_prism(const std::string& name, Polygon2 outline, double z0, double z1,
                    double reflectance, bool* reversed) {
  const bool rev = normalize_outline(outline, "obstacle \"" + name + "\"");
  if (reversed) *reversed = rev;
  if (!(z0 < z1)) {
    throw InputError("obstacle \"" + name + "\": prism z0 must be below z1, got " +
                     format_number(z0) + " and " + format_number(z1));
  }
  return Obstacle{name, std::move(outline), z0, z1, reflectance};
}

namespace {
// Vertical quad over the edge a->b between z0 and z1; `outward_right` chooses the normal: the
// right of a->b (out of a counter-clockwise obstacle) or the left (into a counter-clockwise room).
Face vertical_face(const Vec2& a, const Vec2& b, double z0, double z1, bool normal_right) {
  Face f;
  const Vec2 e = glm::normalize(b - a);
  if (normal_right) {
    f.corners = {{a.x, a.y, z0}, {b.x, b.y, z0}, {b.x, b.y, z1}, {a.x, a.y, z1}};
    f.normal = Vec3(e.y, -e.x, 0.0);
  } else {
    f.corners = {{b.x, b.y, z0}, {a.x, a.y, z0}, {a.x, a.y, z1}, {b.x, b.y, z1}};
    f.normal = Vec3(-e.y, e.x, 0.0);
  }
  return f;
}

Face horizontal_face(const Polygon2& ccw, double z, bool up) {
  Face f;
  for (const auto& p : ccw) f.corners.emplace_back(p.x, p.y, z);
  if (!up) std::reverse(f.corners.begin(), f.corners.end());
  f.normal = Vec3(0, 0, up ? 1.0 : -1.0);
  return f;
}
}  // namespace

std::vector<Face> room_faces(const RoomShape& room) {
  std::vector<Face> faces;
  const std::string who = "room \"" + room.name + "\" ";
  const double z1 = room.floor_z + room.height;
  Face floor = horizontal_face(room.outline, room.floor_z, true);
  floor.kind = Face::Kind::floor;
  floor.label = who + "floor";
  floor.reflectance = room.floor_reflectance;
  faces.push_back(std::move(floor));
  Face ceiling = horizontal_face(room.outline, z1, false);
  ceiling.kind = Face::Kind::ceiling;
  ceiling.label = who + "ceiling";
  ceiling.reflectance = room.ceiling_reflectance;
  faces.push_back(std::move(ceiling));
  const size_t n = room.outline.size();
  for (size_t k = 0; k < n; ++k) {
    Face w = vertical_face(room.outline[k], room.outline[(k + 1) % n], room.floor_z, z1, false);
    w.kind = Face::Kind::wall;
    w.label = who + "wall " + std::to_string(k);
    w.reflectance = room.wall_reflectance;
    faces.push_back(std::move(w));
  }
  return faces;
}

std::vector<Face> obstacle_faces(const Obstacle& o) {
  std::vector<Face> faces;
  const std::string who = "obstacle \"" + o.name + "\" ";
  const size_t n = o.footprint.size();
  for (size_t k = 0; k < n; ++k) {
    Face s = vertical_face(o.footprint[k], o.footprint[(k + 1) % n], o.z0, o.z1, true);
    s.label = who + "side " + std::to_string(k);
    faces.push_back(std::move(s));
  }
  Face top = horizontal_face(o.footprint, o.z1, true);
  top.label = who + "top";
  faces.push_back(std::move(top));
  Face bottom = horizontal_face(o.footprint, o.z0, false);
  bottom.label = who + "bottom";
  faces.push_back(std::move(bottom));
  for (auto& f : faces) {
    f.kind = Face::Kind::obstacle;
    f.reflectance = o.reflectance;
  }
  return faces;
}

std::vector<std::array<Vec3, 3>> triangulate_face(const Face& face) {
  // Project onto the coordinate plane the face is most nearly parallel to, keeping the
  // orientation counter-clockwise there, and ear-clip in 2D.
  const Vec3 an = glm::abs(face.normal);
  const int drop = an.x >= an.y && an.x >= an.z ? 0 : (an.y >= an.z ? 1 : 2);
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  const bool flip = face.normal[drop] < 0.0;
  Polygon2 flat;
  for (const auto& c : face.corners) flat.emplace_back(c[u], c[v]);
  std::vector<int> order(flat.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  if (flip) {
    std::reverse(flat.begin(), flat.end());
    std::reverse(order.begin(), order.end());
  }
  std::vector<std::array<Vec3, 3>> tris;
  for (const auto& t : triangulate(flat)) {
    std::array<Vec3, 3> tri = {face.corners[order[t[0]]], face.corners[order[t[1]]],
                               face.corners[order[t[2]]]};
    tris.push_back(tri);
  }
  return tris;
}

double face_area(const Face& face) {
  double area = 0.0;
  for (const auto& t : triangulate_face(face)) {
    area += 0.5 * glm::length(glm::cross(t[1] - t[0], t[2] - t[0]));
  }
  return area;
}

}  // namespace luxgrid::geometry
