#include "calc/indirect/polygon.h"

#include <limits>
#include <stdexcept>

namespace luxgrid::calc::indirect {

namespace {
double cross2(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }
double orient(const Vec2& a, const Vec2& b, const Vec2& c) { return cross2(b - a, c - a); }
}  // namespace

double signed_area2(const Polygon2& p) {
  double s = 0.0;
  for (size_t i = 0, n = p.size(); i < n; ++i) s += cross2(p[i], p[(i + 1) % n]);
  return s;
}

Vec3 area_vector(const Polygon3& p) {
  Vec3 s(0.0);
  for (size_t i = 0, n = p.size(); i < n; ++i) s += glm::cross(p[i], p[(i + 1) % n]);
  return 0.5 * s;
}

Vec3 polygon_centroid(const Polygon3& p) {
  // Fan from the first vertex; triangle centroids weighted by their (signed, projected) area.
  if (p.empty()) return Vec3(0.0);
  const Vec3 n = area_vector(p);
  const double nn = glm::length(n);
  Vec3 mean(0.0);
  for (const auto& v : p) mean += v;
  mean /= static_cast<double>(p.size());
  if (!(nn > 0.0)) return mean;
  const Vec3 u = n / nn;
  Vec3 c(0.0);
  double a = 0.0;
  for (size_t i = 1; i + 1 < p.size(); ++i) {
    const double t = 0.5 * glm::dot(u, glm::cross(p[i] - p[0], p[i + 1] - p[0]));
    c += t * (p[0] + p[i] + p[i + 1]) / 3.0;
    a += t;
  }
  return std::abs(a) > 0.0 ? c / a : mean;
}

double polygon_diameter(const Polygon3& p) {
  double d = 0.0;
  for (size_t i = 0; i < p.size(); ++i)
    for (size_t j = i + 1; j < p.size(); ++j) d = std::max(d, glm::length(p[i] - p[j]));
  return d;
}

bool point_in_polygon(const Polygon2& poly, const Vec2& q) {
  bool inside = false;
  for (size_t i = 0, n = poly.size(), j = n - 1; i < n; j = i++) {
    const Vec2& a = poly[i];
    const Vec2& b = poly[j];
    if ((a.y > q.y) != (b.y > q.y)) {
      const double x = a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (q.x < x) inside = !inside;
    }
  }
  return inside;
}

double distance_to_boundary(const Polygon2& poly, const Vec2& q) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0, n = poly.size(); i < n; ++i) {
    const Vec2 a = poly[i], b = poly[(i + 1) % n];
    const Vec2 ab = b - a;
    const double L2 = glm::dot(ab, ab);
    const double t = L2 > 0.0 ? std::clamp(glm::dot(q - a, ab) / L2, 0.0, 1.0) : 0.0;
    best = std::min(best, glm::length(q - (a + t * ab)));
  }
  return best;
}

std::vector<Polygon2> ear_clip(const Polygon2& poly) {
  if (poly.size() < 3) throw std::invalid_argument("ear_clip: polygon has fewer than 3 vertices");
  std::vector<size_t> idx(poly.size());
  for (size_t i = 0; i < idx.size(); ++i) idx[i] = i;
  std::vector<Polygon2> tris;
  while (idx.size() > 3) {
    bool clipped = false;
    for (size_t k = 0; k < idx.size(); ++k) {
      const size_t ip = idx[(k + idx.size() - 1) % idx.size()], ic = idx[k],
                   in = idx[(k + 1) % idx.size()];
      const Vec2 a = poly[ip], b = poly[ic], c = poly[in];
      if (orient(a, b, c) <= 0.0) continue;  // reflex or degenerate corner
      bool empty = true;
      for (size_t m : idx) {
        if (m == ip || m == ic || m == in) continue;
        const Vec2 q = poly[m];
        if (orient(a, b, q) >= 0.0 && orient(b, c, q) >= 0.0 && orient(c, a, q) >= 0.0) {
          empty = false;
          break;
        }
      }
      if (!empty) continue;
      tris.push_back({a, b, c});
      idx.erase(idx.begin() + static_cast<std::ptrdiff_t>(k));
      clipped = true;
      break;
    }
    if (!clipped) throw std::invalid_argument("ear_clip: no ear found (outline not simple?)");
  }
  tris.push_back({poly[idx[0]], poly[idx[1]], poly[idx[2]]});
  return tris;
}

Polygon2 clip_convex(const Polygon2& subject, const Polygon2& clip) {
  Polygon2 out = subject;
  for (size_t i = 0, n = clip.size(); i < n && !out.empty(); ++i) {
    const Vec2 a = clip[i], b = clip[(i + 1) % n];
    Polygon2 in;
    in.swap(out);
    for (size_t k = 0, m = in.size(); k < m; ++k) {
      const Vec2 p = in[k], q = in[(k + 1) % m];
      const double dp = orient(a, b, p), dq = orient(a, b, q);
      if (dp >= 0.0) out.push_back(p);
      if ((dp >= 0.0) != (dq >= 0.0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
    }
  }
  return out;
}

Polygon3 clip_to_half_space(const Polygon3& poly, const Vec3& origin, const Vec3& n) {
  Polygon3 out;
  for (size_t k = 0, m = poly.size(); k < m; ++k) {
    const Vec3 p = poly[k], q = poly[(k + 1) % m];
    const double dp = glm::dot(n, p - origin), dq = glm::dot(n, q - origin);
    if (dp >= 0.0) out.push_back(p);
    if ((dp >= 0.0) != (dq >= 0.0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
  }
  return out;
}

bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double o1 = orient(a, b, c), o2 = orient(a, b, d);
  const double o3 = orient(c, d, a), o4 = orient(c, d, b);
  return ((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0)) &&
         ((o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0));
}

}  // namespace luxgrid::calc::indirect
