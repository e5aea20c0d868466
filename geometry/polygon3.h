#pragma once
// Planar polygons in space (patches, luminous openings, clipped openings): area vector,
// centroid, diameter, the half-space clip and the closest point, on plain doubles (no CGAL), for
// code that runs per patch or per point. Two containers: Polygon3 on the heap, FixedPolygon3 of
// a fixed capacity on the stack for the hot paths (a near-field model or a form factor per
// receiver point allocates nothing). The flat outlines these come from are in polygon.h.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "util/robust_math.h"

namespace luxgrid::geometry {

using Polygon3 = std::vector<Vec3>;

// Area vector of a planar polygon (Newell's method): |result| = area (m^2), direction = the
// normal of the side from which the corners run counter-clockwise.
Vec3 area_vector(const Polygon3& p);

// Area-weighted centroid of a planar polygon.
Vec3 polygon_centroid(const Polygon3& p);

// Largest distance between two corners (m).
double polygon_diameter(const Polygon3& p);

// A planar polygon of at most Capacity corners, v[0..n), held on the stack.
template <int Capacity>
struct FixedPolygon3 {
  std::array<Vec3, Capacity> v;
  int n = 0;
};

// The horizon clip's tolerance: a corner counts as on the plane when its height is at most this
// times the polygon's reach (its farthest corner from the origin); see below.
inline constexpr double kOnPlaneTolerance = 64.0 * std::numeric_limits<double>::epsilon();

// The horizon clip: `corners[0..count)` (count <= Capacity) clipped to the half-space
// n . (y - origin) >= 0, returned relative to `origin` (corner - origin): Sutherland-Hodgman, a
// corner on the plane kept once, each crossing projected exactly onto the plane (so a receiver's
// cosine there is 0, never < 0). Heights within rounding of the plane count as on it: for a
// polygon lying in the plane the computed heights are +-rounding with arbitrary signs, and every
// sign change would add a crossing corner (up to 2 count of them); a height below a few ulps of
// the polygon's reach carries no geometric information, so snapping it loses nothing. A convex
// polygon gains at most one corner; a non-convex one is cut short rather than overflow Capacity.
// Fewer than three corners: nothing lies above the plane.
namespace detail {
// The corners relative to the origin, rel[count], their heights over the plane, h[count], and the
// on-plane tolerance (kOnPlaneTolerance times the reach, taken as the root of the largest
// squared length: one square root instead of one per corner, the same value, the root being
// monotonic and correctly rounded).
template <class Buffer, class Heights>
double relative_heights(const Vec3* corners, int count, const Vec3& origin, const Vec3& n,
                        Buffer& rel, Heights& h) {
  double reach2 = 0.0;
  for (int i = 0; i < count; ++i) {
    rel[i] = corners[i] - origin;
    h[i] = glm::dot(rel[i], n);
    reach2 = std::max(reach2, glm::dot(rel[i], rel[i]));
  }
  return kOnPlaneTolerance * std::sqrt(reach2);
}

// The clip of clip_to_half_space_relative on caller-provided buffers rel[count], h[count];
// `emit(corner)` receives the clipped corners while `room()` allows two more.
template <class Buffer, class Heights, class Emit, class Room>
void clip_relative(const Vec3* corners, int count, const Vec3& origin, const Vec3& n, Buffer& rel,
                   Heights& h, Emit&& emit, Room&& room) {
  const double on_plane = relative_heights(corners, count, origin, n, rel, h);
  for (int i = 0; i < count; ++i) {
    if (std::abs(h[i]) <= on_plane) {
      rel[i] -= h[i] * n;
      h[i] = 0.0;
    }
  }
  for (int i = 0; i < count; ++i) {
    const int j = i + 1 < count ? i + 1 : 0;
    if (!room()) break;
    if (h[i] >= 0.0) emit(rel[i]);
    if ((h[i] > 0.0 && h[j] < 0.0) || (h[i] < 0.0 && h[j] > 0.0)) {
      // Strictly between the two corners: opposite signs, so the division is safe, t in (0, 1).
      const double t = h[i] / (h[i] - h[j]);
      Vec3 p = rel[i] + t * (rel[j] - rel[i]);
      p -= glm::dot(p, n) * n;
      emit(p);
    }
  }
}
}  // namespace detail

template <int Capacity>
FixedPolygon3<Capacity> clip_to_half_space_relative(const Vec3* corners, int count,
                                                    const Vec3& origin, const Vec3& n) {
  FixedPolygon3<Capacity> out;
  if (count < 3 || count > Capacity) return out;
  std::array<Vec3, Capacity> rel;
  std::array<double, Capacity> h;
  detail::clip_relative(
      corners, count, origin, n, rel, h, [&](const Vec3& p) { out.v[out.n++] = p; },
      [&] { return out.n + 2 <= Capacity; });
  return out;
}

// The corners relative to `origin` in rel[0..count) (count <= Capacity) when every one lies
// above the plane n . (y - origin) = 0 by more than the clip's on-plane tolerance: then true, and
// rel is what clip_to_half_space_relative would return, to the bit, without its copy and its
// branches (most patches seen from close by lie wholly in front of the receiver).
template <size_t Capacity>
bool relative_if_wholly_above(const Vec3* corners, int count, const Vec3& origin, const Vec3& n,
                              std::array<Vec3, Capacity>& rel) {
  if (count < 3 || count > static_cast<int>(Capacity)) return false;
  std::array<double, Capacity> h;
  const double on_plane = detail::relative_heights(corners, count, origin, n, rel, h);
  return *std::min_element(h.begin(), h.begin() + count) > on_plane;
}

// `poly` clipped to the half-space n . (y - origin) >= 0 as clip_to_half_space_relative, in world
// coordinates, any number of corners (set-up code: clipped openings).
Polygon3 clip_to_half_space(const Polygon3& poly, const Vec3& origin, const Vec3& n);

// The point of a convex polygon nearest to `q`, both in the polygon's plane (unit normal
// `plane_normal`, corners counter-clockwise about it). Inside (or on the boundary): q itself,
// edge -1. Outside: on edge `edge` (from corner edge to corner edge + 1) at parameter t in
// [0, 1]; the first edge wins a tie, and edges of zero length are skipped.
struct ClosestPoint {
  bool inside = false;
  int edge = -1;
  double t = 0.0;
  Vec3 point{0.0};
};
template <int Capacity>
ClosestPoint closest_point(const FixedPolygon3<Capacity>& poly, const Vec3& q,
                           const Vec3& plane_normal) {
  ClosestPoint out;
  const int n = poly.n;
  out.inside = true;
  for (int i = 0; i < n && out.inside; ++i) {
    const Vec3 edge = poly.v[(i + 1) % n] - poly.v[i];
    if (glm::dot(glm::cross(edge, q - poly.v[i]), plane_normal) < 0.0) out.inside = false;
  }
  if (out.inside) {
    out.point = q;
    return out;
  }
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const Vec3 edge = poly.v[(i + 1) % n] - poly.v[i];
    const double len2 = glm::dot(edge, edge);
    if (!(len2 > 0.0)) continue;
    const double t = std::clamp(glm::dot(q - poly.v[i], edge) / len2, 0.0, 1.0);
    const Vec3 diff = poly.v[i] + t * edge - q;
    const double d2 = glm::dot(diff, diff);
    if (d2 < best) {
      best = d2;
      out.edge = i;
      out.t = t;
    }
  }
  if (out.edge >= 0)
    out.point = poly.v[out.edge] + out.t * (poly.v[(out.edge + 1) % n] - poly.v[out.edge]);
  return out;
}

}  // namespace luxgrid::geometry
