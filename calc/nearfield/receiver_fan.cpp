#include "calc/nearfield/receiver_fan.h"

#include <algorithm>
#include <cmath>

namespace luxgrid::nearfield {

OpeningPolygon clip_to_horizon(const Emitter& e, const Vec3& point, const Vec3& normal) {
  return geometry::clip_to_half_space_relative<kMaxPolygonVertices>(
      e.vertices.data(), static_cast<int>(e.vertices.size()), point, normal);
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

  const OpeningPolygon poly = clip_to_horizon(e, fan.receiver, normal);
  const int n = poly.n;
  if (n < 3) return fan;

  // Foot of the receiver on the emitter plane, relative to the receiver.
  const Vec3 foot = -s_shifted * e.normal;
  const geometry::ClosestPoint cp = geometry::closest_point(poly, foot, e.normal);
  if (cp.inside) {
    fan.cp_case = ClosestPointCase::inside;
    fan.apex = foot;
    fan.triangles = n;
    for (int i = 0; i <= n; ++i) fan.rim[i] = poly.v[i % n];
    return fan;
  }
  const int best_edge = std::max(0, cp.edge);
  const double best_t = cp.t;
  if (best_t > 0.0 && best_t < 1.0) {
    // Edge case: apex on edge k, fan over the other n - 1 edges.
    fan.cp_case = ClosestPointCase::edge;
    fan.apex = cp.point;
    fan.triangles = n - 1;
    for (int j = 0; j < n; ++j) fan.rim[j] = poly.v[(best_edge + 1 + j) % n];
    return fan;
  }
  // Vertex case: the apex is the vertex itself, so no zero-area triangles.
  fan.cp_case = ClosestPointCase::vertex;
  const int vtx = best_t <= 0.0 ? best_edge : (best_edge + 1) % n;
  fan.apex = poly.v[vtx];
  fan.triangles = n - 2;
  for (int j = 0; j < n - 1; ++j) fan.rim[j] = poly.v[(vtx + 1 + j) % n];
  return fan;
}

}  // namespace luxgrid::nearfield
