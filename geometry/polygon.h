#pragma once
// Small, fast polygon helpers on plain doubles (no CGAL): areas, convexity, point location and
// ear-clipping triangulation, clipping. Outlines are lists of corners without a repeated closing
// corner. Planar polygons in space are in polygon3.h.
// The CGAL-backed set-up operations (validation with exact predicates, straight-skeleton insets)
// live in room.h and workplane.h (implemented in geometry/cgal/); these helpers are for code that
// runs per point.
#include <array>
#include <string>
#include <vector>

#include "util/robust_math.h"

namespace luxgrid::geometry {

using Polygon2 = std::vector<Vec2>;

// Shoelace area: positive for counter-clockwise corners.
double signed_area(const Polygon2& poly);

// Length of the closed outline: its edges summed in order, the last back to the first corner.
double perimeter(const Polygon2& poly);

// True when every turn of a counter-clockwise polygon is a left turn or straight (collinear
// corners are allowed: a wall split in two is still convex).
bool is_convex(const Polygon2& ccw);

// Euclidean distance from `p` to the segment from `a` to `b` (to `a` when they coincide).
double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b);

enum class Location { inside, boundary, outside };

// Where `p` lies relative to a simple polygon (either orientation). `boundary_tol_m` is the
// distance within which a point counts as on an edge.
Location locate(const Vec2& p, const Polygon2& poly, double boundary_tol_m = 1e-9);

// Ear-clipping triangulation of a simple counter-clockwise polygon: indices into `ccw`, each
// triangle counter-clockwise. Collinear corners are clipped away without emitting a sliver.
std::vector<std::array<int, 3>> triangulate(const Polygon2& ccw);

// The triangles of triangulate() as counter-clockwise polygons of three corners.
std::vector<Polygon2> triangles(const Polygon2& ccw);

// Sutherland-Hodgman: `subject` clipped by the convex counter-clockwise polygon `clip`.
Polygon2 clip_convex(const Polygon2& subject, const Polygon2& clip);

// True when segment ab crosses segment cd at a point inside both (touching at an end point or
// overlapping collinearly does not count).
bool segments_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);

// True when two simple polygons share interior area (touching along an edge or at a corner is
// not overlap). Set-up code: O(n m).
bool polygons_overlap(const Polygon2& a, const Polygon2& b);

// Where `q` lies against edge k of `outline` (from corner k to corner k + 1): `along_m` along the
// edge from corner k, `inside_m` off it towards `inward`, the unit normal on the side where a
// counter-clockwise outline's interior lies. `length_m` is 0 (and the rest unset) for an edge of
// zero length.
struct EdgeCoordinates {
  double length_m = 0.0;
  double along_m = 0.0;
  double inside_m = 0.0;
  Vec2 inward{0.0};
};
EdgeCoordinates edge_coordinates(const Polygon2& outline, size_t k, const Vec2& q);

}  // namespace luxgrid::geometry
