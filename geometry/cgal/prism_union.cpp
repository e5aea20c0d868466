#include "geometry/prism_union.h"

#include <algorithm>
#include <iterator>
#include <numeric>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

namespace luxgrid::geometry {

namespace {
// Exact constructions: the corners of a union are intersections of edges, and whether two
// footprints share area or only an edge must not depend on rounding.
using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = K::Point_2;
using Polygon = CGAL::Polygon_2<K>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<K>;

Point exact(const Vec2& p) { return {p.x, p.y}; }

Polygon exact(const Polygon2& poly) {
  Polygon out;
  for (const Vec2& p : poly) out.push_back(exact(p));
  return out;
}

// The corners of a counter-clockwise polygon without those lying on the line of their
// neighbours: two outlines describe the same point set exactly when these cycles are equal.
std::vector<Point> without_collinear(std::vector<Point> corners) {
  bool removed = true;
  while (removed && corners.size() > 3) {
    removed = false;
    for (size_t k = 0; k < corners.size() && corners.size() > 3; ++k) {
      const size_t n = corners.size();
      if (CGAL::collinear(corners[(k + n - 1) % n], corners[k], corners[(k + 1) % n])) {
        corners.erase(corners.begin() + static_cast<std::ptrdiff_t>(k));
        removed = true;
      }
    }
  }
  return corners;
}

// The cycle started at its lowest corner (smallest x, then y), so equal point sets compare equal.
std::vector<Point> canonical(const Polygon2& poly) {
  std::vector<Point> c;
  for (const Vec2& p : poly) c.push_back(exact(p));
  c = without_collinear(std::move(c));
  std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
  return c;
}

bool share_area(const Polygon2& a, const Polygon2& b) {
  std::vector<PolygonWithHoles> common;
  // The regularised intersection: empty when the footprints only touch along edges or corners.
  CGAL::intersection(exact(a), exact(b), std::back_inserter(common));
  return !common.empty();
}

// Some edge of `a` and some edge of `b` lie on one line and overlap over a positive length.
bool share_edge_length(const Polygon2& a, const Polygon2& b) {
  for (size_t i = 0; i < a.size(); ++i) {
    const Point p = exact(a[i]), q = exact(a[(i + 1) % a.size()]);
    for (size_t j = 0; j < b.size(); ++j) {
      const Point r = exact(b[j]), s = exact(b[(j + 1) % b.size()]);
      if (!CGAL::collinear(p, q, r) || !CGAL::collinear(p, q, s)) continue;
      // On one line: compare along x unless the line is vertical.
      const bool along_x = p.x() != q.x();
      auto lo_hi = [&](const Point& u, const Point& v) {
        const K::FT cu = along_x ? u.x() : u.y(), cv = along_x ? v.x() : v.y();
        return std::pair<K::FT, K::FT>(CGAL::min(cu, cv), CGAL::max(cu, cv));
      };
      const auto [a_lo, a_hi] = lo_hi(p, q);
      const auto [b_lo, b_hi] = lo_hi(r, s);
      if (CGAL::max(a_lo, b_lo) < CGAL::min(a_hi, b_hi)) return true;
    }
  }
  return false;
}

struct Box2 {
  double x0, y0, x1, y1;
};

Box2 bounds(const Polygon2& poly) {
  Box2 b{poly[0].x, poly[0].y, poly[0].x, poly[0].y};
  for (const Vec2& p : poly) {
    b.x0 = std::min(b.x0, p.x), b.y0 = std::min(b.y0, p.y);
    b.x1 = std::max(b.x1, p.x), b.y1 = std::max(b.y1, p.y);
  }
  return b;
}

size_t find_root(std::vector<size_t>& parent, size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// The union of `group` (input indices, ascending) as one obstacle, or nothing when it is no
// prism (see the header).
std::optional<Obstacle> union_of(const std::vector<Obstacle>& in,
                                 const std::vector<size_t>& group) {
  const Obstacle& first = in[group.front()];
  for (size_t k : group)
    if (in[k].reflectance != first.reflectance) return std::nullopt;
  const std::vector<Point> shape = canonical(first.footprint);
  bool same_footprint = true, same_heights = true;
  for (size_t k : group) {
    same_footprint = same_footprint && canonical(in[k].footprint) == shape;
    same_heights = same_heights && in[k].z0 == first.z0 && in[k].z1 == first.z1;
  }
  if (same_footprint) {
    // The z ranges must join into one interval (no gap between stacked pieces).
    std::vector<std::pair<double, double>> z;
    for (size_t k : group) z.emplace_back(in[k].z0, in[k].z1);
    std::sort(z.begin(), z.end());
    double top = z.front().second;
    for (const auto& [z0, z1] : z) {
      if (z0 > top) return std::nullopt;
      top = std::max(top, z1);
    }
    Obstacle out = first;
    out.z0 = z.front().first;
    out.z1 = top;
    return out;
  }
  if (!same_heights) return std::nullopt;
  std::vector<Polygon> pieces;
  for (size_t k : group) pieces.push_back(exact(in[k].footprint));
  std::vector<PolygonWithHoles> joined;
  CGAL::join(pieces.begin(), pieces.end(), std::back_inserter(joined));
  if (joined.size() != 1 || joined.front().number_of_holes() != 0) return std::nullopt;
  const Polygon& outer = joined.front().outer_boundary();
  std::vector<Point> corners(outer.vertices_begin(), outer.vertices_end());
  corners = without_collinear(std::move(corners));
  std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
  if (!Polygon(corners.begin(), corners.end()).is_simple()) return std::nullopt;
  Obstacle out = first;
  out.footprint.clear();
  for (const Point& p : corners)
    out.footprint.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
  return out;
}

}  // namespace

PrismContact prism_contact(const Polygon2& a, double a_z0, double a_z1, const Polygon2& b,
                           double b_z0, double b_z1) {
  const double z_lo = std::max(a_z0, b_z0), z_hi = std::min(a_z1, b_z1);
  if (z_lo > z_hi) return PrismContact::apart;
  // Bounding boxes apart: no exact test needed (a thousand rooms are compared pairwise).
  const Box2 p = bounds(a), q = bounds(b);
  if (p.x0 > q.x1 || q.x0 > p.x1 || p.y0 > q.y1 || q.y0 > p.y1) return PrismContact::apart;
  if (z_lo < z_hi) {
    if (share_area(a, b)) return PrismContact::overlap;
    return share_edge_length(a, b) ? PrismContact::share_face : PrismContact::apart;
  }
  // One stands on the other: a face pressed against a face where the footprints share area.
  return share_area(a, b) ? PrismContact::share_face : PrismContact::apart;
}

ObstacleUnion unite_obstacles(const std::vector<Obstacle>& in) {
  const size_t n = in.size();
  // Pairs that meet, found by sweeping the footprints' bounding boxes along x (closed boxes:
  // touching counts), then tested exactly.
  std::vector<Box2> box(n);
  for (size_t i = 0; i < n; ++i) box[i] = bounds(in[i].footprint);
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t{0});
  std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return box[i].x0 < box[j].x0; });
  struct Pair {
    size_t i, j;
    PrismContact contact;
  };
  std::vector<Pair> meeting;
  for (size_t u = 0; u < n; ++u) {
    const size_t i = order[u];
    for (size_t v = u + 1; v < n && box[order[v]].x0 <= box[i].x1; ++v) {
      const size_t j = order[v];
      if (box[j].y0 > box[i].y1 || box[i].y0 > box[j].y1) continue;
      if (in[j].z0 > in[i].z1 || in[i].z0 > in[j].z1) continue;
      const PrismContact c =
          prism_contact(in[i].footprint, in[i].z0, in[i].z1, in[j].footprint, in[j].z0, in[j].z1);
      if (c != PrismContact::apart) meeting.push_back({std::min(i, j), std::max(i, j), c});
    }
  }
  ObstacleUnion out;
  if (meeting.empty()) {
    out.obstacles = in;
    for (size_t i = 0; i < n; ++i) out.members.push_back({i});
    return out;
  }
  std::sort(meeting.begin(), meeting.end(),
            [](const Pair& a, const Pair& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
  std::vector<size_t> parent(n);
  std::iota(parent.begin(), parent.end(), size_t{0});
  for (const Pair& p : meeting) parent[find_root(parent, p.j)] = find_root(parent, p.i);
  // Groups in the order of their first member, members ascending.
  std::vector<std::vector<size_t>> groups;
  std::vector<size_t> group_of_root(n, n);
  for (size_t i = 0; i < n; ++i) {
    const size_t r = find_root(parent, i);
    if (group_of_root[r] == n) group_of_root[r] = groups.size(), groups.emplace_back();
    groups[group_of_root[r]].push_back(i);
  }
  for (const auto& group : groups) {
    if (group.size() == 1) {
      out.obstacles.push_back(in[group.front()]);
      out.members.push_back(group);
      continue;
    }
    std::optional<Obstacle> u = union_of(in, group);
    if (!u) {
      // The first pair of the group that meets (every group of two or more has one).
      const size_t root = find_root(parent, group.front());
      const auto p = std::find_if(meeting.begin(), meeting.end(),
                                  [&](const Pair& m) { return find_root(parent, m.i) == root; });
      out.obstacles.clear();
      out.members.clear();
      out.conflict = ObstacleUnion::Conflict{p->i, p->j, p->contact};
      return out;
    }
    out.obstacles.push_back(std::move(*u));
    out.members.push_back(group);
  }
  return out;
}

}  // namespace luxgrid::geometry
