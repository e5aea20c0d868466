#pragma once
// Grids over polygonal regions: the workplane (room outline inset by a border, CGAL straight-
// skeleton offset) and the floor and ceiling grids of room_surfaces. No CGAL in this header.
//
// Policy for points that are not part of the surface: the grid stays the full nu x nv rectangle
// over the region's bounding box (row-major, cell centres), so plots and CSV files keep their
// shape; points outside the region or inside an obstacle get active = false and are counted in
// SurfaceGrid::points_outside and SurfaceGrid::points_in_obstacles. Statistics skip them.
#include <string>
#include <vector>

#include "geometry/polygon.h"
#include "geometry/room.h"
#include "geometry/surface_grid.h"

namespace luxgrid::geometry {

// The region `ccw` shrunk by `border_m` on every side (CGAL interior straight-skeleton offset,
// so L-shapes and notches inset correctly). May split into several polygons, or vanish (empty
// result) when the border is too wide. border_m == 0 returns the outline itself.
std::vector<Polygon2> inset_outline(const Polygon2& ccw, double border_m);

struct Bounds2 {
  Vec2 lo{0.0}, hi{0.0};
  double longer_side() const { return std::max(hi.x - lo.x, hi.y - lo.y); }
};
Bounds2 bounds(const std::vector<Polygon2>& region);

// Horizontal grid at height z over the bounding box of `region` with cells of at most
// `spacing_m` (make_plane_grid). A point is active when it lies inside or on the boundary of a
// polygon of the region and not strictly inside the footprint of an obstacle that spans z
// (z0 <= z <= z1: a 0.7 m table does not remove points of a 0.8 m workplane; a 1.8 m cabinet
// does). `normal_up` = false gives a ceiling grid (normal -z, u = +x, v = -y).
SurfaceGrid make_region_grid(const std::string& name, const std::vector<Polygon2>& region, double z,
                             double spacing_m, const std::vector<Obstacle>& obstacles,
                             bool normal_up = true);

// Automatic grids on every face of a room: "<prefix> floor", "<prefix> ceiling",
// "<prefix> wall k" (k as in room_faces). `spacing_m` <= 0 picks auto_spacing per face from the
// face's longer side. Wall grids run along the wall (u from corner k+1 to corner k, so that
// u x v points into the room) and up (v = +z).
std::vector<SurfaceGrid> make_room_surface_grids(const std::string& prefix, const RoomShape& room,
                                                 double spacing_m,
                                                 const std::vector<Obstacle>& obstacles);

}  // namespace luxgrid::geometry
