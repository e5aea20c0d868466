#include "calc/nearfield/receiver_fan.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace luxgrid::nearfield {

SmallPolygon clip_to_horizon(const Emitter& e, const Vec3& point, const Vec3& normal) {
  SmallPolygon out;
  const int n = static_cast<int>(e.vertices.size());
  if (n < 3) return out;
  std::array<Vec3, kMaxPolygonVertices> rel;
  std::array<double, kMaxPolygonVertices> h;
  double reach = 0.0;
  for (int i = 0; i < n; ++i) {
    rel[i] = e.vertices[i] - point;
    h[i] = glm::dot(rel[i], normal);
    reach = std::max(reach, glm::length(rel[i]));
  }
  // Heights within rounding of the plane count as on it. Why: for a polygon lying in the horizon
  // plane the computed heights are +-rounding with arbitrary signs, and every sign change would
  // add a crossing vertex -- up to 2n of them, past the fixed capacity. A height below a few ulps
  // of the polygon's reach carries no geometric information, so snapping it loses nothing.
  const double on_plane = 64.0 * std::numeric_limits<double>::epsilon() * reach;
  for (int i = 0; i < n; ++i) {
    if (std::abs(h[i]) <= on_plane) {
      rel[i] -= h[i] * normal;
      h[i] = 0.0;
    }
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    const bool in_i = h[i] >= 0.0;
    // A convex polygon clipped by a plane has at most n + 1 vertices; the guard only keeps a
    // non-convex input (never produced by make_emitter) from writing past the array.
    if (out.n + 2 > kMaxPolygonVertices) break;
    if (in_i) out.v[out.n++] = rel[i];
    if ((h[i] > 0.0 && h[j] < 0.0) || (h[i] < 0.0 && h[j] > 0.0)) {
      // Crossing strictly between the two vertices (a vertex on the plane is kept by itself,
      // never duplicated): opposite signs, so the division is safe and t is in (0, 1).
      const double t = h[i] / (h[i] - h[j]);
      Vec3 p = rel[i] + t * (rel[j] - rel[i]);
      p -= glm::dot(p, normal) * normal;  // exactly on the horizon, so G = 0 there, never < 0
      out.v[out.n++] = p;
    }
  }
  return out;
}

ShiftedReceiver shift_off_emitter_plane(const Emitter& e, const Vec3& point, double shift_m) {
  const double s = glm::dot(point - e.centroid, e.normal);
  double s_shifted = s;
  if (std::abs(s) < shift_m) s_shifted = (s < 0.0 ? -shift_m : shift_m);
  return {point + (s_shifted - s) * e.normal, std::abs(s_shifted), s_shifted >= 0.0};
}

ReceiverFan build_fan(const Emitter& e, const Vec3& point, const Vec3& normal, double shift_m) {
  ReceiverFan fan;
  fan.normal = normal;
  const ShiftedReceiver shifted = shift_off_emitter_plane(e, point, shift_m);
  fan.receiver = shifted.point;
  fan.plane_distance = shifted.plane_distance;
  fan.front = shifted.front;
  const double s_shifted = shifted.front ? shifted.plane_distance : -shifted.plane_distance;

  const SmallPolygon poly = clip_to_horizon(e, fan.receiver, normal);
  const int n = poly.n;
  if (n < 3) return fan;

  // Foot of the receiver on the emitter plane, relative to the receiver.
  const Vec3 foot = -s_shifted * e.normal;
  bool inside = true;
  for (int i = 0; i < n && inside; ++i) {
    const Vec3 edge = poly.v[(i + 1) % n] - poly.v[i];
    if (glm::dot(glm::cross(edge, foot - poly.v[i]), e.normal) < 0.0) inside = false;
  }
  if (inside) {
    fan.cp_case = ClosestPointCase::inside;
    fan.apex = foot;
    fan.triangles = n;
    for (int i = 0; i <= n; ++i) fan.rim[i] = poly.v[i % n];
    return fan;
  }
  // Clamp the foot to the boundary: nearest point over all edges.
  double best = std::numeric_limits<double>::infinity();
  int best_edge = 0;
  double best_t = 0.0;
  for (int i = 0; i < n; ++i) {
    const Vec3 edge = poly.v[(i + 1) % n] - poly.v[i];
    const double len2 = glm::dot(edge, edge);
    if (!(len2 > 0.0)) continue;
    const double t = std::clamp(glm::dot(foot - poly.v[i], edge) / len2, 0.0, 1.0);
    const Vec3 diff = poly.v[i] + t * edge - foot;
    const double d2 = glm::dot(diff, diff);
    if (d2 < best) {
      best = d2;
      best_edge = i;
      best_t = t;
    }
  }
  if (best_t > 0.0 && best_t < 1.0) {
    // Edge case: apex on edge k, fan over the other n - 1 edges.
    fan.cp_case = ClosestPointCase::edge;
    const Vec3 edge = poly.v[(best_edge + 1) % n] - poly.v[best_edge];
    fan.apex = poly.v[best_edge] + best_t * edge;
    fan.triangles = n - 1;
    for (int j = 0; j < n; ++j) fan.rim[j] = poly.v[(best_edge + 1 + j) % n];
    return fan;
  }
  // Vertex case: the apex is the vertex itself, so no zero-area triangles (issue item 1).
  fan.cp_case = ClosestPointCase::vertex;
  const int vtx = best_t <= 0.0 ? best_edge : (best_edge + 1) % n;
  fan.apex = poly.v[vtx];
  fan.triangles = n - 2;
  for (int j = 0; j < n - 1; ++j) fan.rim[j] = poly.v[(vtx + 1 + j) % n];
  return fan;
}

}  // namespace luxgrid::nearfield
