#include "calc/nearfield/table_psi_cells.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "calc/nearfield/gauss_legendre.h"
#include "util/table_angle.h"

namespace luxgrid::nearfield {
namespace {

// Appends every copy (period 2 pi) of the break at angle x, direction (c, s), that falls strictly
// inside (lo, hi).
inline void add_periodic_break(double x, double c, double s, double lo, double hi,
                               std::vector<Break>& out) {
  for (x = first_copy_at_or_above(x, lo); x < hi; x += kTwoPi)
    if (x > lo) out.push_back({x, c, s});
}

// Appends the directions (as breaks inside (lo, hi)) where the circle of radius r around the
// origin crosses the polygon's edges.
void add_circle_crossings(const Polygon2& p, double r, double lo, double hi,
                          std::vector<Break>& out) {
  const double r2 = r * r, inv_r = 1.0 / r;
  for (int i = 0; i < p.n; ++i) {
    const glm::dvec2 a = p.v[i], e = p.edge[i];
    // |a + u e|^2 = r^2, u in [0, 1]
    const double qa = p.edge_len2[i], qb = p.start_dot_edge[i], qc = p.start_len2[i] - r2;
    if (!(qa > 0.0)) continue;
    const double disc = qb * qb - qa * qc;
    if (!(disc > 0.0)) continue;
    const double root = std::sqrt(disc);
    // u = numerator / qa (qa > 0): a numerator outside (0, qa) puts u outside (0, 1), so only
    // the others are divided (most roots miss the edge) and tested as before.
    for (double numerator : {-qb - root, -qb + root}) {
      if (!(numerator > 0.0 && numerator < qa)) continue;
      const double u = numerator / qa;
      if (u > 0.0 && u < 1.0) {
        const glm::dvec2 x = a + u * e, dir = x * inv_r;
        add_periodic_break(unit_direction_angle(dir.y, dir.x), dir.x, dir.y, lo, hi, out);
      }
    }
  }
}

// True when neither edge `near` nor `far` (-1: none) of the polygon is parallel to a ray at angles
// within one part's width of the gap [a, z] (directions given), the gap cut into `parts` equal
// parts: rho(psi) = cross / det(psi) on the edge a ray enters or leaves through has its poles
// where det vanishes, and its complex poles lie no nearer (tan(gamma') = x / det: at det = +-i x).
// det of an edge is |e| sin(psi - psi_e): over a range narrower than a half turn it vanishes iff
// its sign changes between the range's ends.
bool far_from_parallel(const Polygon2& p, int near, int far, const Break& a, const Break& z,
                       int parts) {
  const double width = z.psi - a.psi, margin = width / parts;
  if (!(width + 2.0 * margin < kPi)) return false;
  double c0, s0, c1, s1;  // a turned back by margin, z turned on by margin
  if (parts == 1) {
    // Without trigonometry: a turned back by the gap is z mirrored in a, z turned on is a
    // mirrored in z (most wide gaps get one rule).
    const double dot2 = 2.0 * (a.c * z.c + a.s * z.s);
    c0 = dot2 * a.c - z.c, s0 = dot2 * a.s - z.s;
    c1 = dot2 * z.c - a.c, s1 = dot2 * z.s - a.s;
  } else {
    const double cm = std::cos(margin), sm = std::sin(margin);
    c0 = a.c * cm + a.s * sm, s0 = a.s * cm - a.c * sm;
    c1 = z.c * cm - z.s * sm, s1 = z.s * cm + z.c * sm;
  }
  for (const int i : {near, far})
    if (i >= 0 && !(edge_det(p, i, c0, s0) * edge_det(p, i, c1, s1) > 0.0)) return false;
  return true;
}

// Sorted breaks of [lo, hi] with no cell wider than max_cell, or a wider gap (no kink inside it:
// every kink is a break) integrated by one Gauss-Legendre rule. A gap of `pieces` x max_cell is
// not cut into pieces of two nodes each but gets one rule of pieces + 1 nodes, exact to degree
// 2 pieces + 1 where the pieces' pairs are exact to degree 3 on each: fewer rays for an
// integrand analytic across the gap, as long as its nearest singularity (the rays parallel to an
// edge they cross: far_from_parallel) lies at least a gap's width beyond it (docs/nearfield.md,
// "Wide gaps"); nearer, the pieces as before. Gaps of more than kMaxGaussLegendrePoints - 1 pieces
// are cut first into equal parts of at most that many, each part's direction turned from the gap's
// first. `out` is scratch space.
void finish_breaks(const Polygon2& poly, const PsiCells& psi, std::vector<Break>& b,
                   std::vector<Break>& out, const Break& lo, const Break& hi, double max_cell) {
  b.push_back(lo);
  b.push_back(hi);
  std::sort(b.begin(), b.end(), [](const Break& x, const Break& y) { return x.psi < y.psi; });
  out.clear();
  out.push_back(b.front());
  constexpr int kMaxPiecesPerRule = kMaxGaussLegendrePoints - 1;
  for (std::size_t i = 1; i < b.size(); ++i) {
    const Break a = out.back(), z = b[i];
    if (!(z.psi - a.psi > kMinCell)) continue;
    const int pieces = pieces_of_at_most((z.psi - a.psi) / max_cell);
    if (pieces > 1) {
      const int by_rule = (pieces + kMaxPiecesPerRule - 1) / kMaxPiecesPerRule;
      // The edges the gap's rays cross, from its middle ray (F outside: its near and far edge).
      int near = -1, far = -1;
      bool edges_known = false;
      if (psi.outside) {
        edges_known = psi.edges_of(a.psi + 0.5 * (z.psi - a.psi), poly.n, near, far);
      } else {
        const double mc = a.c + z.c, ms = a.s + z.s;
        far = exit_edge(poly, mc, ms);
        edges_known = far >= 0;
      }
      const bool rule = edges_known && far_from_parallel(poly, near, far, a, z, by_rule);
      const int parts = rule ? by_rule : pieces;
      const int points = rule ? (pieces + parts - 1) / parts + 1 : 2;
      out.back().points = points;
      if (parts > 1) {
        const double step = (z.psi - a.psi) / parts, cs = std::cos(step), sn = std::sin(step);
        double c = a.c, s = a.s;
        for (int k = 1; k < parts; ++k) {
          const double c_next = c * cs - s * sn;
          s = s * cs + c * sn, c = c_next;
          out.push_back({a.psi + (z.psi - a.psi) * k / parts, c, s, points});
        }
      }
    }
    out.push_back(z);
  }
  b.swap(out);
}

}  // namespace

bool psi_cells(const Polygon2& poly, bool inside, bool front, double abs_sigma, double reach,
               const TableGammaCells& cells, const std::vector<double>& c_lines, PsiCells& out,
               std::vector<Break>& scratch) {
  std::vector<Break>& b = out.breaks;
  b.clear();
  if (poly.n < 3) return false;                        // (the caller's clip has 3 or more corners)
  std::array<double, kMaxPolygonVertices> vertex_psi;  // each vertex's direction from F
  std::array<glm::dvec2, kMaxPolygonVertices> vertex_dir;
  for (int i = 0; i < poly.n; ++i) {
    const double len = glm::length(poly.v[i]);
    vertex_dir[i] = len > 0.0 ? poly.v[i] / len : glm::dvec2(1.0, 0.0);
    vertex_psi[i] = unit_direction_angle(vertex_dir[i].y, vertex_dir[i].x);
  }
  Break lo_break, hi_break;
  out.outside = !inside;
  if (inside) {
    lo_break = {vertex_psi[0], vertex_dir[0].x, vertex_dir[0].y};
    hi_break = {vertex_psi[0] + kTwoPi, vertex_dir[0].x, vertex_dir[0].y};
  } else {
    glm::dvec2 mid(0.0);
    for (int i = 0; i < poly.n; ++i) mid += poly.v[i];
    const double psi_mid = direction_angle(mid.y, mid.x);
    std::array<double, kMaxPolygonVertices> rel;
    double lo = 0.0, hi = 0.0;
    int i_lo = 0, i_hi = 0;
    for (int i = 0; i < poly.n; ++i) {
      double d = vertex_psi[i] - psi_mid;
      // Into [-pi, pi]: d is within a turn of 0 (both angles are in (-pi, pi]).
      if (d > kPi) d -= kTwoPi;
      if (d < -kPi) d += kTwoPi;
      rel[i] = d;
      if (d < lo) lo = d, i_lo = i;
      if (d > hi) hi = d, i_hi = i;
    }
    lo_break = {psi_mid + lo, vertex_dir[i_lo].x, vertex_dir[i_lo].y};
    hi_break = {psi_mid + hi, vertex_dir[i_hi].x, vertex_dir[i_hi].y};
    out.psi_mid = psi_mid;
    double area2 = 0.0;
    for (int i = 0; i < poly.n; ++i) area2 += -poly.cross[i];  // a x b = -cross
    for (int i = 0; i < poly.n; ++i) {
      const int j = (i + 1) % poly.n;
      out.span_lo[i] = std::min(rel[i], rel[j]);
      out.span_hi[i] = std::max(rel[i], rel[j]);
      out.facing[i] = -poly.cross[i] * area2 < 0.0;  // F on the edge's outer side
    }
  }
  const double psi_lo = lo_break.psi, psi_hi = hi_break.psi;
  if (!(psi_hi - psi_lo > kMinCell)) return false;
  for (int i = 0; i < poly.n; ++i)
    add_periodic_break(vertex_psi[i], vertex_dir[i].x, vertex_dir[i].y, psi_lo, psi_hi, b);
  const std::size_t c_count = c_lines.size();
  if (c_count > 1 && inside) {
    for (std::size_t k = 0; k < c_count; ++k)
      add_periodic_break(c_lines[k] - kPi, cells.c_break_cos[k], cells.c_break_sin[k], psi_lo,
                         psi_hi, b);
  } else if (c_count > 1) {
    // F outside: the range is narrower than a half turn, so a C line has at most one copy in
    // it, and the lines that have one follow each other (cyclically) from the first line past
    // the range's start: only those are tried, from one line earlier (the start's rounding) to
    // the first whose copy lies beyond the range. Each copy is add_periodic_break's.
    const double c_start = first_copy_at_or_above(psi_lo + kPi, 0.0);
    std::size_t k = static_cast<std::size_t>(
        std::upper_bound(c_lines.begin(), c_lines.end(), c_start) - c_lines.begin());
    k = (k + c_count - 1) % c_count;
    for (std::size_t tried = 0; tried < c_count; ++tried, k = (k + 1) % c_count) {
      const double x = first_copy_at_or_above(c_lines[k] - kPi, psi_lo);
      if (x >= psi_hi) {
        if (tried == 0) continue;
        break;
      }
      if (x > psi_lo) b.push_back({x, cells.c_break_cos[k], cells.c_break_sin[k]});
    }
  }
  // A circle crosses the outline only between the outline's nearest point and its farthest
  // vertex (reach): the circles inside the nearest distance are skipped without solving for their
  // crossings (a margin of 1e-9 keeps a circle through the nearest point).
  double nearest2 = std::numeric_limits<double>::infinity();
  for (int i = 0; i < poly.n; ++i) {
    const glm::dvec2 a = poly.v[i], e = poly.v[(i + 1) % poly.n] - a;
    const double ee = glm::dot(e, e);
    const double u = ee > 0.0 ? std::clamp(-glm::dot(a, e) / ee, 0.0, 1.0) : 0.0;
    const glm::dvec2 q = a + u * e;
    nearest2 = std::min(nearest2, glm::dot(q, q));
  }
  const double nearest = std::sqrt(nearest2) * (1.0 - 1e-9);
  // The lines in order of gamma' from 0 (ascending in front, descending behind), so their radii
  // grow: the first beyond the reach ends the loop.
  const double* lines = cells.lines.data();
  const double* line_tan = cells.line_tan.data();
  const std::size_t count = cells.lines.size();
  // The circles inside the nearest distance, found by bisection: in this order a line's gamma'
  // grows, and so does its radius up to pi / 2, so they are a prefix of the steps.
  const auto inside_nearest = [&](std::size_t step) {
    const std::size_t k = front ? step : count - 1 - step;
    const double gp = front ? lines[k] : kPi - lines[k];
    return gp < 0.5 * kPi && (!(gp > 0.0) || abs_sigma * line_tan[k] < nearest);
  };
  std::size_t first_step = 0;
  for (std::size_t last = count; first_step < last;) {
    const std::size_t mid = first_step + (last - first_step) / 2;
    if (inside_nearest(mid))
      first_step = mid + 1;
    else
      last = mid;
  }
  for (std::size_t step = first_step; step < count; ++step) {
    const std::size_t k = front ? step : count - 1 - step;
    const double gp = front ? lines[k] : kPi - lines[k];
    if (!(gp > 0.0)) continue;
    if (!(gp < 0.5 * kPi)) break;
    const double r = abs_sigma * line_tan[k];
    if (!(r < reach)) break;
    if (r >= nearest) add_circle_crossings(poly, r, psi_lo, psi_hi, b);
  }
  finish_breaks(poly, out, b, scratch, lo_break, hi_break, kMaxPsiCell);
  return true;
}

}  // namespace luxgrid::nearfield
