#include "geometry/workplane.h"

#include "geometry/wall_clearance.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/create_offset_polygons_2.h>

#include "util/format.h"

namespace luxgrid::geometry {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalPolygon = CGAL::Polygon_2<K>;

// Offset corners land within rounding of where they should (an inset of a 4 x 3 m rectangle by
// 0.5 m may give 0.5000000000000001). Rounding to the nearest 1e-9 m decimal when that moves the
// value by no more than rounding noise restores the exact grid positions users expect (and
// tests compare) without moving any genuine corner.
constexpr double kSnapRelativeNoise = 1e-12;
double snap(double x) {
  const double s = std::strtod(format_double("%.9f", x).c_str(), nullptr);
  return std::abs(s - x) <= kSnapRelativeNoise * std::max(1.0, std::abs(x)) ? s : x;
}
}  // namespace

// The straight skeleton's offset when every corner is convex (left turn or straight, by CGAL's
// exact orientation predicate); otherwise the erosion of wall_clearance.h. Both sets of corners
// are rounded to nearby 1e-9 m decimals alike.
InsetRegion inset_region(const Polygon2& ccw, double border_m) {
  if (border_m <= 0.0) return {{ccw}};
  CgalPolygon poly;
  for (const auto& p : ccw) poly.push_back(K::Point_2(p.x, p.y));
  bool has_reflex_corner = false;
  for (size_t k = 0, n = ccw.size(); k < n; ++k) {
    has_reflex_corner =
        has_reflex_corner ||
        CGAL::orientation(poly[(k + n - 1) % n], poly[k], poly[(k + 1) % n]) == CGAL::RIGHT_TURN;
  }
  InsetRegion out;
  std::vector<Polygon2> raw;
  if (has_reflex_corner) {
    raw = wall_clearance_region(ccw, border_m);
    out.walls = &ccw, out.border_m = border_m;
  } else {
    for (const auto& op : CGAL::create_interior_skeleton_and_offset_polygons_2(border_m, poly)) {
      Polygon2 q;
      for (auto v = op->vertices_begin(); v != op->vertices_end(); ++v)
        q.emplace_back(CGAL::to_double(v->x()), CGAL::to_double(v->y()));
      raw.push_back(std::move(q));
    }
  }
  for (auto& q : raw) {
    for (auto& v : q) v = Vec2(snap(v.x), snap(v.y));
    if (q.size() >= 3 && signed_area(q) < 0.0) std::reverse(q.begin(), q.end());
    if (q.size() >= 3 && std::abs(signed_area(q)) > 0.0) out.polygons.push_back(std::move(q));
  }
  return out;
}

std::vector<Polygon2> inset_outline(const Polygon2& ccw, double border_m) {
  return inset_region(ccw, border_m).polygons;
}

Bounds2 bounds(const std::vector<Polygon2>& region) {
  Bounds2 b{Vec2(INFINITY), Vec2(-INFINITY)};
  for (const auto& poly : region) {
    for (const auto& p : poly) {
      b.lo = glm::min(b.lo, p);
      b.hi = glm::max(b.hi, p);
    }
  }
  return b;
}

SurfaceGrid make_region_grid(const std::string& name, const std::vector<Polygon2>& region, double z,
                             double spacing_m, const std::vector<Obstacle>& obstacles,
                             bool normal_up) {
  return make_region_grid(name, InsetRegion{region}, z, spacing_m, obstacles, normal_up);
}

SurfaceGrid make_region_grid(const std::string& name, const InsetRegion& inset, double z,
                             double spacing_m, const std::vector<Obstacle>& obstacles,
                             bool normal_up) {
  const std::vector<Polygon2>& region = inset.polygons;
  const Bounds2 b = bounds(region);
  const double su = b.hi.x - b.lo.x, sv = b.hi.y - b.lo.y;
  SurfaceGrid g = normal_up ? make_plane_grid(name, Vec3(b.lo.x, b.lo.y, z), Vec3(1, 0, 0),
                                              Vec3(0, 1, 0), su, sv, spacing_m)
                            : make_plane_grid(name, Vec3(b.lo.x, b.hi.y, z), Vec3(1, 0, 0),
                                              Vec3(0, -1, 0), su, sv, spacing_m);
  g.region = region;
  std::vector<const Obstacle*> cutting;
  for (const auto& o : obstacles) {
    if (o.z0 <= z && z <= o.z1) cutting.push_back(&o);
  }
  // Exact predicates for the region test: a cell centre on an inset edge must not flip between
  // runs or compilers.
  // With walls: the outline's exact test, then the distance to each wall.
  std::vector<CgalPolygon> cgal_region;
  for (const auto& poly : inset.walls ? std::vector<Polygon2>{*inset.walls} : region) {
    CgalPolygon c;
    for (const auto& p : poly) c.push_back(K::Point_2(p.x, p.y));
    cgal_region.push_back(std::move(c));
  }
  for (size_t i = 0; i < g.points.size(); ++i) {
    const K::Point_2 p(g.points[i].x, g.points[i].y);
    bool in_region = false;
    for (const auto& c : cgal_region) {
      if (c.bounded_side(p) != CGAL::ON_UNBOUNDED_SIDE) {
        in_region = !inset.walls || clear_of_walls(Vec2(g.points[i]), *inset.walls, inset.border_m);
        break;
      }
    }
    if (!in_region) {
      g.active[i] = false;
      ++g.points_outside;
      continue;
    }
    for (const Obstacle* o : cutting) {
      if (locate(Vec2(g.points[i]), o->footprint, 0.0) == Location::inside) {
        g.active[i] = false;
        ++g.points_in_obstacles;
        break;
      }
    }
  }
  return g;
}

std::vector<SurfaceGrid> make_room_surface_grids(const std::string& prefix, const RoomShape& room,
                                                 double spacing_m,
                                                 const std::vector<Obstacle>& obstacles) {
  std::vector<SurfaceGrid> out;
  const std::vector<Polygon2> region = {room.outline};
  const double region_spacing =
      spacing_m > 0.0 ? spacing_m : auto_spacing(bounds(region).longer_side());
  out.push_back(
      make_region_grid(prefix + " floor", region, room.floor_z, region_spacing, obstacles, true));
  out.push_back(make_region_grid(prefix + " ceiling", region, room.floor_z + room.height,
                                 region_spacing, obstacles, false));
  const size_t n = room.outline.size();
  for (size_t k = 0; k < n; ++k) {
    const Vec2 a = room.outline[k], b = room.outline[(k + 1) % n];
    const double length = glm::length(b - a);
    const double s = spacing_m > 0.0 ? spacing_m : auto_spacing(std::max(length, room.height));
    const Vec2 u = (a - b) / length;
    out.push_back(make_plane_grid(prefix + " wall " + std::to_string(k),
                                  Vec3(b.x, b.y, room.floor_z), Vec3(u.x, u.y, 0.0), Vec3(0, 0, 1),
                                  length, room.height, s));
  }
  return out;
}

}  // namespace luxgrid::geometry
