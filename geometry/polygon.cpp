#include "geometry/polygon.h"

#include <algorithm>
#include <cmath>

namespace luxgrid::geometry {

namespace {
double cross(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

}  // namespace

double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

double signed_area(const Polygon2& poly) {
  double twice = 0.0;
  for (size_t i = 0, n = poly.size(); i < n; ++i) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[(i + 1) % n];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice;
}

double perimeter(const Polygon2& poly) {
  double length = 0.0;
  for (size_t k = 0, n = poly.size(); k < n; ++k)
    length += glm::length(poly[(k + 1) % n] - poly[k]);
  return length;
}

bool is_convex(const Polygon2& ccw) {
  const size_t n = ccw.size();
  if (n < 3) return false;
  // Relative to the polygon's size, so a 100 m hall and a 1 m niche are judged alike.
  double scale = 0.0;
  for (const auto& p : ccw) scale = std::max(scale, std::max(std::abs(p.x), std::abs(p.y)));
  const double tol = 1e-12 * std::max(1.0, scale * scale);
  for (size_t i = 0; i < n; ++i) {
    if (cross(ccw[i], ccw[(i + 1) % n], ccw[(i + 2) % n]) < -tol) return false;
  }
  return true;
}

Location locate(const Vec2& p, const Polygon2& poly, double boundary_tol_m) {
  const size_t n = poly.size();
  bool inside = false;
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = poly[j];
    const Vec2& b = poly[i];
    if (distance_to_segment(p, a, b) <= boundary_tol_m) return Location::boundary;
    // Crossing-number test with the half-open rule (a vertex on the ray counts once).
    if ((b.y > p.y) != (a.y > p.y)) {
      const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < x) inside = !inside;
    }
  }
  return inside ? Location::inside : Location::outside;
}

std::vector<std::array<int, 3>> triangulate(const Polygon2& ccw) {
  std::vector<std::array<int, 3>> out;
  std::vector<int> idx(ccw.size());
  for (size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<int>(i);
  auto contains = [&](int a, int b, int c, int p) {
    // Closed triangle test, so a reflex corner touching the ear's edge blocks it.
    return cross(ccw[a], ccw[b], ccw[p]) >= 0.0 && cross(ccw[b], ccw[c], ccw[p]) >= 0.0 &&
           cross(ccw[c], ccw[a], ccw[p]) >= 0.0;
  };
  while (idx.size() > 3) {
    const size_t n = idx.size();
    bool clipped = false;
    for (size_t k = 0; k < n && !clipped; ++k) {
      const int a = idx[(k + n - 1) % n], b = idx[k], c = idx[(k + 1) % n];
      if (!(cross(ccw[a], ccw[b], ccw[c]) > 0.0)) continue;  // reflex or straight: no ear
      bool empty = true;
      for (size_t m = 0; m < n && empty; ++m) {
        const int p = idx[m];
        if (p == a || p == b || p == c) continue;
        if (ccw[p] == ccw[a] || ccw[p] == ccw[b] || ccw[p] == ccw[c]) continue;
        if (contains(a, b, c, p)) empty = false;
      }
      if (empty) {
        out.push_back({a, b, c});
        idx.erase(idx.begin() + static_cast<std::ptrdiff_t>(k));
        clipped = true;
      }
    }
    if (!clipped) {
      // Only straight corners (or rounding) are left between ears: drop the flattest corner,
      // which removes no area.
      size_t best = 0;
      double best_abs = INFINITY;
      for (size_t k = 0; k < n; ++k) {
        const double c =
            std::abs(cross(ccw[idx[(k + n - 1) % n]], ccw[idx[k]], ccw[idx[(k + 1) % n]]));
        if (c < best_abs) {
          best_abs = c;
          best = k;
        }
      }
      idx.erase(idx.begin() + static_cast<std::ptrdiff_t>(best));
    }
  }
  if (idx.size() == 3 && cross(ccw[idx[0]], ccw[idx[1]], ccw[idx[2]]) > 0.0) {
    out.push_back({idx[0], idx[1], idx[2]});
  }
  return out;
}

std::vector<Polygon2> triangles(const Polygon2& ccw) {
  std::vector<Polygon2> out;
  for (const auto& t : triangulate(ccw)) out.push_back({ccw[t[0]], ccw[t[1]], ccw[t[2]]});
  return out;
}

Polygon2 clip_convex(const Polygon2& subject, const Polygon2& clip) {
  Polygon2 out = subject;
  for (size_t i = 0, n = clip.size(); i < n && !out.empty(); ++i) {
    const Vec2 a = clip[i], b = clip[(i + 1) % n];
    Polygon2 in;
    in.swap(out);
    for (size_t k = 0, m = in.size(); k < m; ++k) {
      const Vec2 p = in[k], q = in[(k + 1) % m];
      const double dp = cross(a, b, p), dq = cross(a, b, q);
      if (dp >= 0.0) out.push_back(p);
      if ((dp >= 0.0) != (dq >= 0.0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
    }
  }
  return out;
}

bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double d1 = cross(a, b, c), d2 = cross(a, b, d), d3 = cross(c, d, a), d4 = cross(c, d, b);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

namespace {

Polygon2 counter_clockwise_copy(const Polygon2& p) {
  Polygon2 out = p;
  if (signed_area(out) < 0.0) std::reverse(out.begin(), out.end());
  return out;
}

}  // namespace

bool polygons_overlap(const Polygon2& a, const Polygon2& b) {
  for (size_t i = 0; i < a.size(); ++i) {
    for (size_t j = 0; j < b.size(); ++j) {
      if (segments_cross(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()])) return true;
    }
  }
  // No proper crossing: one may still hold part of the other, inside it or beside it along
  // collinear edges (two rectangles of one height, side by side and overlapping along x, cross
  // nowhere properly and need not hold a corner or a triangle's centroid of the other). The area
  // they share decides, triangle by triangle (each convex, so Sutherland-Hodgman clips it
  // exactly); polygons that only touch along an edge or at a corner share round-off: 1e-9 of
  // the smaller area.
  const Polygon2 ccw_a = counter_clockwise_copy(a), ccw_b = counter_clockwise_copy(b);
  const double tolerance =
      1e-9 * std::min(std::abs(signed_area(ccw_a)), std::abs(signed_area(ccw_b)));
  double shared = 0.0;
  for (const Polygon2& ta : triangles(ccw_a)) {
    for (const Polygon2& tb : triangles(ccw_b)) {
      shared += std::abs(signed_area(clip_convex(ta, tb)));
      if (shared > tolerance) return true;
    }
  }
  return false;
}

EdgeCoordinates edge_coordinates(const Polygon2& outline, size_t k, const Vec2& q) {
  EdgeCoordinates e;
  const Vec2 a = outline[k], b = outline[(k + 1) % outline.size()];
  e.length_m = glm::length(b - a);
  if (!(e.length_m > 0.0)) return e;
  const Vec2 t = (b - a) / e.length_m;
  e.inward = Vec2(-t.y, t.x);
  e.along_m = glm::dot(q - a, t);
  e.inside_m = glm::dot(q - a, e.inward);
  return e;
}

}  // namespace luxgrid::geometry
