#pragma once
// Small polygon helpers for the patch mesh and the form factors of calc/indirect. They stand in
// for geometry/ (CGAL) until the room-face builder lands; each is exact for the convex, planar
// polygons the patch mesh produces.
#include <vector>

#include "util/robust_math.h"

namespace luxgrid::calc::indirect {

using Polygon2 = std::vector<Vec2>;
using Polygon3 = std::vector<Vec3>;

// Twice the signed area of a 2D polygon (> 0 for counter-clockwise).
double signed_area2(const Polygon2& p);

// Area vector of a planar 3D polygon (Newell's method): |result| = area, direction = the normal
// of the counter-clockwise side.
Vec3 area_vector(const Polygon3& p);

// Area-weighted centroid of a planar 3D polygon.
Vec3 polygon_centroid(const Polygon3& p);

// Largest distance between two vertices (m).
double polygon_diameter(const Polygon3& p);

// Even-odd point-in-polygon test (points exactly on an edge may go either way).
bool point_in_polygon(const Polygon2& poly, const Vec2& q);

// Distance from q to the polygon's boundary (m).
double distance_to_boundary(const Polygon2& poly, const Vec2& q);

// Ear clipping of a simple counter-clockwise polygon into counter-clockwise triangles.
// Throws std::invalid_argument for fewer than 3 vertices or a polygon that is not simple enough
// to be clipped (no ear found).
std::vector<Polygon2> ear_clip(const Polygon2& poly);

// Sutherland-Hodgman: `subject` clipped by the convex counter-clockwise polygon `clip`.
Polygon2 clip_convex(const Polygon2& subject, const Polygon2& clip);

// `poly` clipped to the half-space n . (y - origin) >= 0 (the horizon clip).
Polygon3 clip_to_half_space(const Polygon3& poly, const Vec3& origin, const Vec3& n);

// True when segment ab properly crosses segment cd (touching at an end point does not count).
bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);

}  // namespace luxgrid::calc::indirect
