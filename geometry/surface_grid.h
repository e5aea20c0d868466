#pragma once
// Calculation surfaces turned into points with normals. Grids run along u first, then v
// (row-major, size = [nu, nv]); points sit at cell centres.
#include <string>
#include <vector>

#include "util/robust_math.h"

namespace luxgrid::geometry {

// What a surface's numbers mean (project key "quantity"):
// - planar: illuminance on each point's own normal (the default; the surface normal).
// - horizontal: on a face looking up (the loader sets every normal to +z).
// - vertical: on a vertical face (the loader sets every normal horizontal: "facing" or the
//   horizontal part of the surface normal).
// - cylindrical: mean vertical illuminance around a vertical axis through the point,
//   E_cyl = I sin(eps) / (pi d^2) for a point source at angle eps from the vertical; normals keep
//   the surface normal and are not used by the calculation.
// - semi_cylindrical: mean vertical illuminance over the half cylinder facing a horizontal
//   direction, E_sc = I sin(eps) (1 + cos(alpha)) / (pi d^2) for a point source (EN 13201-2);
//   the loader sets every normal to that facing direction (as for vertical).
enum class Quantity { planar, horizontal, vertical, cylindrical, semi_cylindrical };
const char* to_string(Quantity q);

struct SurfaceGrid {
  // observers: eye positions with viewing directions for glare (calc/glare); one point per
  // (observer, view), its normal the view direction, so the direct and indirect calculations
  // give the illuminance at the eye on a plane facing the view.
  enum class Kind { grid, points, observers };
  std::string name;
  Kind kind = Kind::grid;
  int nu = 0, nv = 0;      // grid size; for points: nu = count, nv = 1
  double spacing_u = 0.0;  // m, actual cell size along u (0 for points)
  double spacing_v = 0.0;
  Vec3 origin{0.0}, u_dir{1, 0, 0}, v_dir{0, 1, 0};  // grid frame (unit u, v), for plots
  double size_u = 0.0, size_v = 0.0;                 // extent of the gridded rectangle, m
  std::vector<Vec3> points;
  std::vector<Vec3> normals;
  std::vector<bool> active;  // false for points left out (below); same size as points
  // Points left out (active = false), by reason; the grid keeps them so it stays nu x nv.
  size_t points_outside = 0;       // outside the (inset) polygon of a workplane/floor/ceiling
  size_t points_in_obstacles = 0;  // inside the footprint of an obstacle spanning the grid
  size_t points_in_openings = 0;   // in a window or roof light of the face the grid covers
  Quantity quantity = Quantity::planar;
  // observers: the observer (index into the surface's list) each point belongs to.
  std::vector<size_t> observer;
  // Region grids (workplane, room floor and ceiling): the plan polygons the active points lie in,
  // counter-clockwise, so plots draw the surface's real outline (an L-shaped workplane as an L);
  // empty for rectangles, walls and points.
  std::vector<std::vector<Vec2>> region;
};

// "grid", "points", "observers": the kind's name in results.json and the Python module.
const char* to_string(SurfaceGrid::Kind kind);

// EN 12464-1 automatic grid spacing: p = 0.2 * 5^log10(d) for the longer side d, capped at 10 m
// (the standard's table caps the spacing; see docs/project-format.md).
double auto_spacing(double longer_side);

// A rectangle from `origin` along unit `u` and `v` directions of `size_u` x `size_v` metres,
// cells of at most `spacing`; normal = u x v.
SurfaceGrid make_plane_grid(const std::string& name, const Vec3& origin, const Vec3& u,
                            const Vec3& v, double size_u, double size_v, double spacing);

}  // namespace luxgrid::geometry
