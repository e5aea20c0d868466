#pragma once
// Grids over polygonal regions: the workplane (room outline less a border along every wall) and
// the floor and ceiling grids of room_surfaces. No CGAL in this header.
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

// The part of the outline `ccw` at least `border_m` from every wall, the workplane inside a
// border. `polygons` bound it (drawn on plots; the grid spans their box): for a convex outline
// the CGAL interior straight-skeleton offset, whose mitred corners are then exact (every corner
// is convex, and a convex corner of the set lies where two moved walls cross); for an outline
// with a reflex corner wall_clearance_region (wall_clearance.h), whose arcs about reflex corners
// the mitred offset would replace by a point shooting inward. `walls`, set for the latter, makes
// the grid decide each point by its distance to the walls (clear_of_walls) rather than by the
// polygons, which only approximate the arcs. May split into several polygons, or vanish (empty
// polygons) when the border is too wide. border_m == 0 gives the outline itself.
struct InsetRegion {
  std::vector<Polygon2> polygons;
  const Polygon2* walls = nullptr;  // the outline (outlives the region), or none
  double border_m = 0.0;
};
InsetRegion inset_region(const Polygon2& ccw, double border_m);

// inset_region(ccw, border_m).polygons.
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
// The same over an inset region: with `region.walls` set, a point is in the region when it lies
// in the outline (boundary included) and clear of its walls by the border.
SurfaceGrid make_region_grid(const std::string& name, const InsetRegion& region, double z,
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
