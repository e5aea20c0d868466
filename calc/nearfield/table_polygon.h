#pragma once
// The table rung's view of the opening (calc/nearfield/table_cubature.cpp): the horizon-clipped
// polygon in the luminaire frame with the receiver's foot F at the origin, and the rays from F
// that the rung integrates along: where a ray at angle psi enters and leaves it.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "calc/nearfield/receiver_fan.h"
#include "util/robust_math.h"

namespace luxgrid::nearfield {

struct Polygon2 {
  std::array<glm::dvec2, kMaxPolygonVertices> v;
  int n = 0;
  // Per edge i (v[i] to v[i + 1]): its vector and a x e, the parts of ray_interval's solve that
  // do not depend on the ray (set by prepare_edges).
  std::array<glm::dvec2, kMaxPolygonVertices> edge;
  std::array<double, kMaxPolygonVertices> cross;
  // And the coefficients of add_circle_crossings' quadratic that do not depend on the circle:
  // e . e, a . e and a . a.
  std::array<double, kMaxPolygonVertices> edge_len2, start_dot_edge, start_len2;
  void prepare_edges() {
    for (int i = 0; i < n; ++i) {
      const glm::dvec2 a = v[i];
      edge[i] = v[(i + 1) % n] - a;
      cross[i] = -a.x * edge[i].y + a.y * edge[i].x;
      edge_len2[i] = glm::dot(edge[i], edge[i]);
      start_dot_edge[i] = glm::dot(a, edge[i]);
      start_len2[i] = glm::dot(a, a);
    }
  }
};

inline bool contains_origin(const Polygon2& p) {
  double area2 = 0.0;
  for (int i = 0; i < p.n; ++i) {
    const glm::dvec2 a = p.v[i], b = p.v[(i + 1) % p.n];
    area2 += a.x * b.y - a.y * b.x;
  }
  for (int i = 0; i < p.n; ++i) {
    const glm::dvec2 a = p.v[i], b = p.v[(i + 1) % p.n];
    // Origin strictly on the outer side of an edge: outside.
    if ((a.x * b.y - a.y * b.x) * area2 < 0.0) return false;
  }
  return true;
}

// The distance along the ray from the origin at angle psi to the line of edge i, for an edge the
// ray is known to cross, is t = cross[i] / edge_det(i) (ray_interval's solve).
inline double edge_det(const Polygon2& p, int i, double cos_psi, double sin_psi) {
  return -cos_psi * p.edge[i].y + sin_psi * p.edge[i].x;
}

// Distances along the ray from the origin at angle psi where it enters and leaves the convex
// polygon. False when the ray misses it (only at the rim of the angular range, by rounding).
inline bool ray_interval(const Polygon2& p, double cos_psi, double sin_psi, bool origin_inside,
                         double& rho_min, double& rho_max) {
  rho_min = std::numeric_limits<double>::infinity();
  rho_max = 0.0;
  bool hit = false;
  for (int i = 0; i < p.n; ++i) {
    const glm::dvec2 a = p.v[i];
    // origin + t (c, s) = a + u e  ->  t (c, s) - u e = a
    const double det = edge_det(p, i, cos_psi, sin_psi);
    if (det == 0.0) continue;
    // u = u_det / det and t = t_det / det, tested without dividing (the ray misses most edges).
    const double u_det = cos_psi * a.y - sin_psi * a.x, t_det = p.cross[i];
    const double abs_det = std::abs(det), sign = det > 0.0 ? 1.0 : -1.0;
    if (sign * u_det < -1e-12 * abs_det || sign * u_det > (1.0 + 1e-12) * abs_det ||
        sign * t_det < 0.0)
      continue;
    const double t = t_det / det;
    rho_min = std::min(rho_min, t);
    rho_max = std::max(rho_max, t);
    hit = true;
  }
  if (origin_inside) rho_min = 0.0;
  return hit && rho_max > rho_min;
}

// The edge the ray from the origin in direction (c, s) leaves a polygon around the origin
// through, or -1 (the ray passes through a vertex).
inline int exit_edge(const Polygon2& p, double c, double s) {
  for (int i = 0; i < p.n; ++i) {
    const double det = edge_det(p, i, c, s);
    if (det == 0.0) continue;
    const double u = (c * p.v[i].y - s * p.v[i].x) / det, t = p.cross[i] / det;
    if (u > 0.0 && u < 1.0 && t > 0.0) return i;
  }
  return -1;
}

}  // namespace luxgrid::nearfield
