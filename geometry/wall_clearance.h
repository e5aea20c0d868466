#pragma once
// The part of a room outline that lies at least a border away from every wall: the outline
// eroded by a disc of the border's radius (a morphological erosion). Along a
// wall it is the wall moved inward by the border; around a reflex corner it is an arc of the
// border's radius about the corner, where a mitred (straight-skeleton) offset shoots a sharp
// point far inward. A border therefore never removes more than its width from any wall.
// Plain doubles, no CGAL: workplane.h chooses it for outlines with a reflex corner.
#include <vector>

#include "geometry/polygon.h"

namespace luxgrid::geometry {

// A point lies clear of the walls when its distance to each of them is at least the border less
// this much: a grid point on the border line itself counts as inside, whatever the rounding of
// its distance (the same 1 nm to which workplane.h rounds inset corners).
inline constexpr double kWallClearanceTolerance_m = 1e-9;

// Whether `p` lies at least `border_m` (less kWallClearanceTolerance_m) from every edge of the
// closed outline `poly`. Stops at the first edge nearer than that.
bool clear_of_walls(const Vec2& p, const Polygon2& poly, double border_m);

// The boundary of { p in ccw : distance to every edge >= border_m } (ccw counter-clockwise,
// simple, border_m > 0) as counter-clockwise polygons, one per connected part (the erosion of a
// simple polygon has no holes). Straight parts are exact: each wall moved inward by border_m and
// cut where it comes within border_m of another wall. Arcs about reflex corners are given by
// their chords, at most kArcStep_rad apart, each ending on the arc (the chords lie just outside
// the set: the polygons are for drawing and for the grid's extent; clear_of_walls decides each
// grid point). The set's extreme coordinates are reached at corners of its boundary, never inside
// an arc (the arcs bend into the set), so the polygons' bounding box is the set's. Empty when
// nothing lies border_m from every wall.
inline constexpr double kArcStep_rad = 0.0872664625997164788;  // 5 degrees
std::vector<Polygon2> wall_clearance_region(const Polygon2& ccw, double border_m);

}  // namespace luxgrid::geometry
