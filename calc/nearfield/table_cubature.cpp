// The table rung (docs/nearfield.md, "The table rung"): the area form of the illuminance
//   E = (1/A) integral over the clipped polygon of I(C, gamma) cos_r / d^2 dA
// in polar coordinates around the receiver's foot F on the emitter plane.
//
// Why polar around F: seen from an emitter point y, the receiver x lies at photometric angles
// gamma = angle between the emitter's axis and (x - y), C = azimuth of (x - y). With y at
// in-plane offset rho (cos psi, sin psi) from F and sigma the receiver's signed distance from
// the plane, gamma' = atan(rho / |sigma|) is gamma (front) or pi - gamma (back) and C = psi + pi.
// So the table's C lines are rays from F and its gamma lines are circles around F: the cells
// of (psi, gamma') between them are exactly the table's cells, inside which a bilinear
// (bicubic) interpolant is smooth. The adaptive rungs sample across those kinks and their error
// indicators misjudge them (docs/accuracy.md); here every kink is a cell boundary and a
// 2 x 2 Gauss-Legendre rule per cell converges like on a smooth function.
//
// The measure: dA / d^2 = rho d rho d psi / d^2 = tan(gamma') d gamma' d psi, and
// cos_r = sin(gamma') (n_x cos psi + n_y sin psi) + sign(sigma) n_z cos(gamma') with n the
// receiver normal in the luminaire frame. tan(gamma') grows without bound towards the plane
// (gamma' -> 90 deg); cells there are split so tan grows by at most kTableTanRatio across each
// (table_cells.h).
//
// Other receivers (receiver_kernel.h): the unit direction to a node is
// u = sin(gamma') a + cos(gamma') axis in the world, a = R (cos psi, sin psi, 0) per ray and
// axis = sign(sigma) R (0, 0, 1), and receiver_weight(receiver, u) replaces cos_r. For a cylinder
// the weight sin(eps) / pi is smooth on the cells except at the one node direction straight up or
// down, where its cone vertex (weight 0) sits; there the integrand is small, so the cell rule's
// error stays far below the rung's tolerance (tests/nearfield/cylindrical_test.cpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "calc/nearfield/fan_sample.h"
#include "calc/nearfield/gauss_legendre.h"
#include "calc/nearfield/models.h"
#include "calc/nearfield/receiver_fan.h"
#include "calc/nearfield/receiver_kernel.h"
#include "calc/nearfield/table_cells.h"
#include "geometry/table_angle_lanes.h"
#include "photometry/tabular_distribution.h"
#include "util/table_angle.h"

namespace luxgrid::nearfield {
namespace {

// Largest angular width of a psi cell (rad, 7.5 deg) when the table has no C line inside it
// (rotationally symmetric files have none): the outline rho(psi) and the weight must still be
// resolved. The gamma side's limits are in table_cells.h.
constexpr double kMaxPsiCell = 7.5 * kPi / 180.0;
// Cells narrower than this (rad) are dropped: two breaks that coincide up to rounding.
constexpr double kMinCell = 1e-12;
// A plane receiver whose normal (unit, luminaire frame) leans off the emitter's axis by at most
// this much in x and y is integrated in closed form along each ray with the radial term of cos_r
// left out: it contributes at most this times sin(gamma') tan(gamma') of the integrand, a relative
// 1e-12 x tan(gamma') (below 1e-9 for every gamma' short of 89.9 degrees). Rotations by multiples
// of 90 degrees leave components of ~1e-16.
constexpr double kAxialNormalTolerance = 1e-12;

struct Polygon2 {
  std::array<glm::dvec2, kMaxPolygonVertices> v;
  int n = 0;
  // Per edge i (v[i] to v[i + 1]): its vector and a x e, the parts of ray_interval's solve that
  // do not depend on the ray (set by prepare_edges).
  std::array<glm::dvec2, kMaxPolygonVertices> edge;
  std::array<double, kMaxPolygonVertices> cross;
  // And the coefficients of add_circle_crossings' quadratic that do not depend on the circle:
  // e . e, a . e and a . a.
  std::array<double, kMaxPolygonVertices> edge_len2, start_dot_edge, start_len2;
  void prepare_edges() {
    for (int i = 0; i < n; ++i) {
      const glm::dvec2 a = v[i];
      edge[i] = v[(i + 1) % n] - a;
      cross[i] = -a.x * edge[i].y + a.y * edge[i].x;
      edge_len2[i] = glm::dot(edge[i], edge[i]);
      start_dot_edge[i] = glm::dot(a, edge[i]);
      start_len2[i] = glm::dot(a, a);
    }
  }
};

bool contains_origin(const Polygon2& p) {
  double area2 = 0.0;
  for (int i = 0; i < p.n; ++i) {
    const glm::dvec2 a = p.v[i], b = p.v[(i + 1) % p.n];
    area2 += a.x * b.y - a.y * b.x;
  }
  for (int i = 0; i < p.n; ++i) {
    const glm::dvec2 a = p.v[i], b = p.v[(i + 1) % p.n];
    // Origin strictly on the outer side of an edge: outside.
    if ((a.x * b.y - a.y * b.x) * area2 < 0.0) return false;
  }
  return true;
}

// The distance along the ray from the origin at angle psi to the line of edge i, for an edge the
// ray is known to cross, is t = cross[i] / edge_det(i) (ray_interval's solve).
double edge_det(const Polygon2& p, int i, double cos_psi, double sin_psi) {
  return -cos_psi * p.edge[i].y + sin_psi * p.edge[i].x;
}

// Distances along the ray from the origin at angle psi where it enters and leaves the convex
// polygon. False when the ray misses it (only at the rim of the angular range, by rounding).
bool ray_interval(const Polygon2& p, double cos_psi, double sin_psi, bool origin_inside,
                  double& rho_min, double& rho_max) {
  rho_min = std::numeric_limits<double>::infinity();
  rho_max = 0.0;
  bool hit = false;
  for (int i = 0; i < p.n; ++i) {
    const glm::dvec2 a = p.v[i];
    // origin + t (c, s) = a + u e  ->  t (c, s) - u e = a
    const double det = edge_det(p, i, cos_psi, sin_psi);
    if (det == 0.0) continue;
    // u = u_det / det and t = t_det / det, tested without dividing (the ray misses most edges).
    const double u_det = cos_psi * a.y - sin_psi * a.x, t_det = p.cross[i];
    const double abs_det = std::abs(det), sign = det > 0.0 ? 1.0 : -1.0;
    if (sign * u_det < -1e-12 * abs_det || sign * u_det > (1.0 + 1e-12) * abs_det ||
        sign * t_det < 0.0)
      continue;
    const double t = t_det / det;
    rho_min = std::min(rho_min, t);
    rho_max = std::max(rho_max, t);
    hit = true;
  }
  if (origin_inside) rho_min = 0.0;
  return hit && rho_max > rho_min;
}

// x - 2 pi floor((x - lo) / 2 pi): the copy of angle x in [lo, lo + 2 pi), the same bits, without
// floor's call for the angles the rung meets (at most a turn away).
inline double first_copy_at_or_above(double x, double lo) {
  const double turns = (x - lo) / kTwoPi;
  if (turns >= 0.0 && turns < 1.0) return x - kTwoPi * 0.0;
  if (turns >= 1.0 && turns < 2.0) return x - kTwoPi * 1.0;
  if (turns >= -1.0 && turns < 0.0) return x - kTwoPi * -1.0;
  return x - kTwoPi * std::floor(turns);
}

// A psi break: its angle and its direction (cos, sin), the direction taken from the geometry
// that made the break (a vertex, a circle crossing, a C plane), so that a cell's middle direction
// is the normalised sum of its ends': no sine and cosine per cell.
struct Break {
  double psi, c, s;
  int points = 2;  // the Gauss-Legendre rule of the cell that starts here (finish_breaks)
};

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

// What psi_cells (below) makes: the breaks, and with F outside each edge's angular span.
struct PsiCells {
  std::vector<Break> breaks;  // sorted
  bool outside = false;
  double psi_mid = 0.0;  // spans are relative to it
  std::array<double, kMaxPolygonVertices> span_lo{}, span_hi{};
  std::array<bool, kMaxPolygonVertices> facing{};

  // The edges a ray at psi (inside the range, F outside) enters and leaves through: false where
  // the spans do not tell (F on an edge's line), and the caller tests every edge.
  bool edges_of(double psi, int n, int& near, int& far) const {
    const double rel = psi - psi_mid;
    near = far = -1;
    for (int i = 0; i < n; ++i)
      if (span_lo[i] < rel && rel < span_hi[i]) (facing[i] ? near : far) = i;
    return near >= 0 && far >= 0;
  }
};

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

// The edge the ray from the origin in direction (c, s) leaves a polygon around the origin
// through, or -1 (the ray passes through a vertex).
int exit_edge(const Polygon2& p, double c, double s) {
  for (int i = 0; i < p.n; ++i) {
    const double det = edge_det(p, i, c, s);
    if (det == 0.0) continue;
    const double u = (c * p.v[i].y - s * p.v[i].x) / det, t = p.cross[i] / det;
    if (u > 0.0 && u < 1.0 && t > 0.0) return i;
  }
  return -1;
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

// A ray of a psi cell: its angle, direction and Gauss weight (1 for the pair's).
struct CellNode {
  double psi, c, s, weight;
};

// sin and cos of |delta| <= kWideSeriesMax by their Taylor series to delta^13 and delta^14: the
// first omitted terms, delta^15 / 15! and delta^16 / 16!, are below 1e-16 of the kept ones there.
// Wider: the library. (gauss_pair, table_cells.h, stops the same series at delta^7 and delta^8
// for its offsets of at most 0.05 rad, the pairs' hot path; a wide gap's offsets reach 0.5 rad.)
constexpr double kWideSeriesMax = 0.55;
inline void sin_cos_of_offset(double delta, double& s, double& c) {
  if (!(std::abs(delta) <= kWideSeriesMax)) {
    s = std::sin(delta), c = std::cos(delta);
    return;
  }
  const double d2 = delta * delta;
  s = delta *
      (1.0 -
       d2 * (1.0 / 6) *
           (1.0 - d2 * (1.0 / 20) *
                      (1.0 - d2 * (1.0 / 42) *
                                 (1.0 - d2 * (1.0 / 72) *
                                            (1.0 - d2 * (1.0 / 110) * (1.0 - d2 * (1.0 / 156)))))));
  c = 1.0 -
      d2 * 0.5 *
          (1.0 - d2 * (1.0 / 12) *
                     (1.0 - d2 * (1.0 / 30) *
                                (1.0 - d2 * (1.0 / 56) *
                                           (1.0 - d2 * (1.0 / 90) *
                                                      (1.0 - d2 * (1.0 / 132) *
                                                                 (1.0 - d2 * (1.0 / 182)))))));
}

// The `points` nodes of the Gauss-Legendre rule on the cell of half-width `half` around the
// middle angle x_mid, direction (cos_mid, sin_mid).
void wide_nodes(int points, double x_mid, double half, double cos_mid, double sin_mid,
                std::array<CellNode, kMaxGaussLegendrePoints>& out) {
  const GaussLegendreRule& rule = gauss_legendre(points);
  for (int i = 0; i < (points + 1) / 2; ++i) {
    const int j = points - 1 - i;  // the mirror node, at -delta
    const double delta = half * rule.x[i];
    double sd, cd;
    sin_cos_of_offset(delta, sd, cd);
    out[i] = {x_mid + delta, cos_mid * cd - sin_mid * sd, sin_mid * cd + cos_mid * sd, rule.w[i]};
    if (j != i)
      out[j] = {x_mid - delta, cos_mid * cd + sin_mid * sd, sin_mid * cd - cos_mid * sd, rule.w[j]};
  }
}

// A ray of the rung's psi cells: its angle and direction, its share 0.5 x cell width x Gauss
// weight, and what its cell's rays share: the table's C cell, the cell's index, and with F
// outside the edges it enters and leaves through (near_edge < 0: every edge is tried).
struct RayJob {
  double psi, c, s, scale;
  photometry::TabularDistribution::CCell c_cell;
  std::size_t cell;
  int near_edge, far_edge;
};

// Where a ray enters and leaves the opening: sin, cos and tan of gamma' and its table angle at
// both ends (ok false: the ray misses the opening, by rounding at the rim of the range).
struct RayEnds {
  bool ok;
  double sin_near, cos_near, sin_far, cos_far, tan_near, tan_far, g_near, g_far;
};

// The ends of four rays that enter and leave through known edges (job.near_edge >= 0), in the
// lanes of one computation (geometry/table_angle_lanes.h): each lane what table_rung's second
// pass computes for its ray, the same operations in the same order, so the same bits.
[[gnu::target_clones("avx2", "default")]] void ends_by_edges4(const Polygon2& poly,
                                                              const RayJob* jobs, double inv_sigma,
                                                              RayEnds* ends) {
  using geometry::lanes::D4;
  using geometry::lanes::L4;
  D4 cp, sp, nx, ny, fx, fy, cross_near, cross_far;
  for (int l = 0; l < 4; ++l) {
    const RayJob& job = jobs[l];
    cp[l] = job.c, sp[l] = job.s;
    nx[l] = poly.edge[job.near_edge].x, ny[l] = poly.edge[job.near_edge].y;
    fx[l] = poly.edge[job.far_edge].x, fy[l] = poly.edge[job.far_edge].y;
    cross_near[l] = poly.cross[job.near_edge], cross_far[l] = poly.cross[job.far_edge];
  }
  // edge_det, rho = cross / det, and (sin, cos) = (|x|, |det|) / sqrt(x^2 + det^2).
  const D4 det_near = -cp * ny + sp * nx, det_far = -cp * fy + sp * fx;
  const D4 rho_min = cross_near / det_near, rho_max = cross_far / det_far;
  const L4 ok = (rho_max > rho_min) & (rho_min >= 0.0);
  const D4 x_near = cross_near * inv_sigma, x_far = cross_far * inv_sigma;
  const D4 r_near = x_near * x_near + det_near * det_near,
           r_far = x_far * x_far + det_far * det_far;
  const D4 root_near = {std::sqrt(r_near[0]), std::sqrt(r_near[1]), std::sqrt(r_near[2]),
                        std::sqrt(r_near[3])};
  const D4 root_far = {std::sqrt(r_far[0]), std::sqrt(r_far[1]), std::sqrt(r_far[2]),
                       std::sqrt(r_far[3])};
  const D4 inv_near = 1.0 / root_near, inv_far = 1.0 / root_far;
  const long long magnitude = ~geometry::lanes::kSignBit;  // |v|: the sign bit cleared
  const D4 cos_near = (D4)((L4)det_near & magnitude) * inv_near,
           sin_near = (D4)((L4)x_near & magnitude) * inv_near;
  const D4 cos_far = (D4)((L4)det_far & magnitude) * inv_far,
           sin_far = (D4)((L4)x_far & magnitude) * inv_far;
  // quadrant_angle(sin, cos) = octant_table_angle(sin, cos, false, 1.0).
  const L4 front = {0, 0, 0, 0};
  const D4 one = {1.0, 1.0, 1.0, 1.0};
  D4 g_near, g_far;
  geometry::lanes::octant_table_angle(sin_near, cos_near, front, one, g_near);
  geometry::lanes::octant_table_angle(sin_far, cos_far, front, one, g_far);
  const D4 tan_near = rho_min * inv_sigma, tan_far = rho_max * inv_sigma;
  for (int l = 0; l < 4; ++l) {
    if (!ok[l]) {
      ends[l].ok = false;
      continue;
    }
    ends[l] = {true,        sin_near[l], cos_near[l], sin_far[l], cos_far[l],
               tan_near[l], tan_far[l],  g_near[l],   g_far[l]};
  }
}

// The psi cells of one receiver: the angular range of the polygon seen from F (all around when
// F is inside), cut at the polygon's vertex directions (rho(psi) has a corner there), at the
// table's C lines (C = psi + pi), and where a gamma line (a circle of radius |sigma| tan gamma'
// around F) crosses the outline: there a ray's first or last gamma cell changes, a kink in psi.
// With F outside, each edge's angular span and whether it faces F: a ray in a cell enters through
// the facing edge whose span holds the cell and leaves through the other (edges_of).

// False when the range is empty.
bool psi_cells(const Polygon2& poly, bool inside, bool front, double abs_sigma, double reach,
               const TableGammaCells& cells, const std::vector<double>& c_lines, PsiCells& out) {
  thread_local std::vector<Break> scratch;
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

// The closed form along rays (below): a bilinear table and a plane normal (unit, luminaire frame)
// along the axis.
bool closed_form_applies(const photometry::TabularDistribution& table, const Vec3& n_local) {
  return table.interpolation() == photometry::Interpolation::bilinear &&
         std::abs(n_local.x) <= kAxialNormalTolerance &&
         std::abs(n_local.y) <= kAxialNormalTolerance;
}

}  // namespace

bool table_rung_in_closed_form(const Emitter& e, const Vec3& normal) {
  const photometry::TableView view =
      e.distribution ? e.distribution->table_view() : photometry::TableView{};
  if (!view.table || e.is_point() || !e.table_cells || e.table_cells->table != view.table)
    return false;
  return closed_form_applies(*view.table, e.world_to_local * normal);
}

bool table_aligned_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal,
                               double& lux) {
  return table_aligned_illuminance(e, point, Receiver::planar(normal), lux);
}

namespace {

// The rung for one receiver (light_vector null: `lux`), or the light vector of the whole opening
// in the luminaire frame, unscaled (light_vector set: the receiver is not used).
bool table_rung(const Emitter& e, const Vec3& point, const Receiver& receiver, double& lux,
                Vec3* light_vector) {
  const photometry::TableView view =
      e.distribution ? e.distribution->table_view() : photometry::TableView{};
  if (!view.table || e.is_point() || !e.table_cells || e.table_cells->table != view.table)
    return false;
  lux = 0.0;
  if (light_vector) *light_vector = Vec3(0.0);
  const ShiftedReceiver shifted = shift_off_emitter_plane(e, point, horizon_shift_m(e));
  const OpeningPolygon clipped =
      clip_to_horizon(e, shifted.point, light_vector ? Vec3(0.0) : receiver.horizon_normal());
  if (clipped.n < 3) return true;

  // Luminaire frame, origin at the (shifted) receiver: a vertex's x, y are its offset from F,
  // its z is sigma (the same for all, up to rounding).
  Polygon2 poly;
  poly.n = clipped.n;
  double sigma = 0.0, reach2 = 0.0;
  for (int i = 0; i < clipped.n; ++i) {
    const Vec3 q = e.world_to_local * clipped.v[i];
    poly.v[i] = glm::dvec2(q.x, q.y);
    sigma += q.z;
    reach2 = std::max(reach2, glm::dot(poly.v[i], poly.v[i]));
  }
  sigma /= clipped.n;
  poly.prepare_edges();
  const double abs_sigma = std::abs(sigma);
  if (!(abs_sigma > 0.0)) return true;  // excluded by the horizon shift
  const bool front = sigma > 0.0;
  const double inv_sigma = 1.0 / abs_sigma;
  // A plane: cos_r from the normal in the luminaire frame (the fast path, no vector per node).
  const bool planar = receiver.kind == ReceiverKind::planar;
  const Vec3 n = e.world_to_local * receiver.direction;
  const double n_z = front ? n.z : -n.z;
  // Any other receiver: the world direction to a node is sin(gamma') a + cos(gamma') axis.
  const Vec3 axis = (front ? 1.0 : -1.0) * e.rotation[2];

  const photometry::TabularDistribution& table = *view.table;
  const TableGammaCells& cells = *e.table_cells;
  const std::vector<double>& lines = cells.lines;

  const bool inside = contains_origin(poly);
  thread_local PsiCells psi;
  thread_local std::vector<TableGammaNode> end_nodes;
  if (!psi_cells(poly, inside, front, abs_sigma, std::sqrt(reach2), cells, table.grid().c_rad, psi))
    return true;
  const std::vector<Break>& psi_breaks = psi.breaks;

  double sum = 0.0;
  // One ray's direction terms: `radial` = n . (cos psi, sin psi, 0) in the luminaire frame for a
  // plane, `a` = R (cos psi, sin psi, 0) for any other receiver.
  struct Ray {
    double radial;
    Vec3 a;
  };
  // The nodes of one ray: weight x receiver weight (cos_r for a plane) x intensity, the table
  // read with the ray's C position.
  auto node_sum = [&](const TableGammaNode* q, const TableGammaNode* end,
                      const photometry::TabularDistribution::CPosition& c, const Ray& ray) {
    double v = 0.0;
    for (; q != end; ++q) {
      const double g = planar ? q->sin_g * ray.radial + n_z * q->abs_cos_g
                              : receiver_weight(receiver, q->sin_g * ray.a + q->abs_cos_g * axis);
      if (!(g > 0.0) || q->row < 0) continue;
      v += q->weight_tan * g * table.intensity_at(c, static_cast<std::size_t>(q->row), q->tg);
    }
    return v;
  };
  // One end cell of a ray: table angles [a, b] with |tan| ta, tb, nodes computed here.
  auto end_cell = [&](double a, double b, double ta, double tb,
                      const photometry::TabularDistribution::CPosition& c, const Ray& ray) {
    end_nodes.clear();
    append_gamma_nodes(table, a, b, ta, tb, end_nodes);
    return node_sum(end_nodes.data(), end_nodes.data() + end_nodes.size(), c, ray);
  };
  // A plane facing the axis (a workplane under a ceiling luminaire, the floor, the ceiling) on a
  // bilinear table: cos_r = n_z cos(gamma'), so along a ray the integrand is n_z I(C, gamma)
  // sin(gamma'), and I is linear in gamma inside each table cell: the gamma integral is exact in
  // closed form (linear_sin_integral), no nodes, no trigonometry but the ray's end angles.
  // Whole intervals read their weights from table_cells.h. Normals off the axis by more than
  // kAxialNormalTolerance keep the nodes (the radial term sin^2 / cos has no elementary integral
  // against a linear I).
  const bool closed_form = !light_vector && planar && closed_form_applies(table, n);
  if (closed_form && !(n_z > 0.0)) return true;  // the receiver faces away: cos_r <= 0 everywhere
  const double* gamma_rows = table.grid().gamma_rad.data();
  const long* interval_row = cells.interval_row.data();
  const double* inv_row_width = cells.inv_row_width.data();
  const std::size_t line_count = lines.size();
  // One ray in closed form: table angles [t_lo, t_hi] (the ray's in-plane reach rho_min, rho_max),
  // the lines strictly inside are [k_lo, k_hi).
  auto closed_ray = [&](double t_lo, double t_hi, double sin_near, double cos_near, double sin_far,
                        double cos_far, std::size_t k_lo, std::size_t k_hi,
                        const photometry::TabularDistribution::CPosition& c) {
    // sin and cos of the table angles at the ray's ends (of gamma' at its near and far end).
    const double s_lo = front ? sin_near : sin_far, s_hi = front ? sin_far : sin_near;
    const double c_lo = front ? cos_near : -cos_far, c_hi = front ? cos_far : -cos_near;
    const photometry::TabularDistribution::CColumns columns = table.c_columns(c);
    // The piece [a, b] of interval k (k < 0 or past the last line: outside the table).
    const auto piece = [&](long k, double a, double sa, double ca, double b, double sb, double cb) {
      if (k < 0 || static_cast<std::size_t>(k) >= line_count) return 0.0;
      const long row = interval_row[k];
      if (row < 0) return 0.0;
      const std::size_t j = static_cast<std::size_t>(row);
      return linear_sin_integral(a, sa, ca, b, sb, cb, gamma_rows[j], inv_row_width[j],
                                 columns.row_value(j), columns.row_value(j + 1));
    };
    const long first = static_cast<long>(k_lo) - 1;
    if (k_lo >= k_hi) return n_z * piece(first, t_lo, s_lo, c_lo, t_hi, s_hi, c_hi);
    double v =
        piece(first, t_lo, s_lo, c_lo, lines[k_lo], cells.line_sin[k_lo], cells.line_cos[k_lo]) +
        piece(static_cast<long>(k_hi) - 1, lines[k_hi - 1], cells.line_sin[k_hi - 1],
              cells.line_cos[k_hi - 1], t_hi, s_hi, c_hi);
    if (k_lo + 1 < k_hi) v += cells.whole_intervals(c, k_lo, k_hi - 1);
    return n_z * v;
  };
  // The light vector: per ray the nodes' moments sum_j w_j I_j (sin, cos) of gamma', no receiver
  // weight and no clamp (the caller's plane sees the whole opening, so cos_r > 0 at every node).
  struct Moments {
    double radial = 0.0, axial = 0.0;
  };
  auto add_moments = [&](const TableGammaNode* q, const TableGammaNode* end,
                         const photometry::TabularDistribution::CPosition& c, Moments& m) {
    for (; q != end; ++q) {
      if (q->row < 0) continue;
      const double wi =
          q->weight_tan * table.intensity_at(c, static_cast<std::size_t>(q->row), q->tg);
      m.radial += wi * q->sin_g;
      m.axial += wi * q->abs_cos_g;
    }
  };
  auto end_moments = [&](double a, double b, double ta, double tb,
                         const photometry::TabularDistribution::CPosition& c, Moments& m) {
    end_nodes.clear();
    append_gamma_nodes(table, a, b, ta, tb, end_nodes);
    add_moments(end_nodes.data(), end_nodes.data() + end_nodes.size(), c, m);
  };
  // Three passes over the rays, each a loop of independent iterations: the rays' ends are a long
  // chain of dependent operations (determinant, square root, division, table angle), and a loop
  // that does only them lets the processor run several rays' chains at once, where one ray's
  // whole work per iteration left it waiting on each chain in turn.
  // 1. The cells' rays, with what a cell's rays share: with F outside, the edges they enter and
  //    leave through (no vertex direction lies inside a cell), and the table's C cell (nor does a
  //    C plane).
  // The buffers are the thread's, grown to the largest count seen; the loops index them through
  // plain pointers and counts (a thread-local vector's size and data would be read again from
  // thread-local storage at every step).
  thread_local std::vector<RayJob> jobs_buffer;
  thread_local std::vector<RayEnds> ends_buffer;
  const std::size_t cell_count = psi_breaks.size() - 1;
  std::size_t ray_count = 0;
  for (std::size_t k = 0; k < cell_count; ++k) ray_count += psi_breaks[k].points;
  if (jobs_buffer.size() < ray_count) jobs_buffer.resize(ray_count), ends_buffer.resize(ray_count);
  RayJob* const jobs = jobs_buffer.data();
  RayEnds* const ends = ends_buffer.data();
  std::size_t job_count = 0;
  photometry::TabularDistribution::CCell c_cell{0, 1.0, 0.0};  // empty: looked up first
  for (std::size_t k = 0; k < cell_count; ++k) {
    const Break& a = psi_breaks[k];
    const Break& b = psi_breaks[k + 1];
    const double pa = a.psi, pw = b.psi - pa;
    // The middle direction from the ends' (a cell spans at most kMaxPsiCell).
    const double mc = a.c + b.c, ms = a.s + b.s, inv_len = 1.0 / std::sqrt(mc * mc + ms * ms);
    // The cell's rays: the Gauss pair, or a wide gap's rule (finish_breaks).
    const double x_mid = pa + 0.5 * pw;
    std::array<CellNode, kMaxGaussLegendrePoints> rays;
    if (a.points == 2) {
      const GaussPair g = gauss_pair(pa, pa + pw, ms * inv_len, mc * inv_len);
      rays[0] = {g.x_lo, g.c_lo, g.s_lo, 1.0}, rays[1] = {g.x_hi, g.c_hi, g.s_hi, 1.0};
    } else {
      wide_nodes(a.points, x_mid, 0.5 * pw, mc * inv_len, ms * inv_len, rays);
    }
    int near_edge = -1, far_edge = -1;
    const bool by_edges = psi.outside && psi.edges_of(x_mid, poly.n, near_edge, far_edge);
    const double c_mid = first_copy_at_or_above(x_mid + kPi, 0.0);
    // Consecutive cells mostly share a C cell: looked up again only when the middle leaves it.
    if (!(c_mid >= c_cell.c0 && c_mid < c_cell.c1)) c_cell = table.c_cell(c_mid);
    for (int node = 0; node < a.points; ++node)
      jobs[job_count++] = {rays[node].psi,
                           rays[node].c,
                           rays[node].s,
                           0.5 * pw * rays[node].weight,
                           c_cell,
                           k,
                           by_edges ? near_edge : -1,
                           far_edge};
  }
  // 2. Each ray's reach [rho_min, rho_max] and the sines, cosines and table angles at its ends;
  //    four rays at once where all four go through known edges (ends_by_edges4).
  const auto ray_ends = [&](std::size_t r) {
    const RayJob& job = jobs[r];
    RayEnds& end = ends[r];
    const double cp = job.c, sp = job.s;
    double rho_min, rho_max, cos_near, cos_far, sin_near, sin_far;
    end.ok = false;
    if (job.near_edge >= 0) {
      // On an edge rho = cross / det, so tan(gamma') = rho / |sigma| = x / det with
      // x = cross / |sigma|, and (sin, cos) = (|x|, |det|) / sqrt(x^2 + det^2): after the
      // determinant one square root and one division, where going through tan takes a
      // division, a square root and another division one after the other.
      const int near_edge = job.near_edge, far_edge = job.far_edge;
      const double det_near = edge_det(poly, near_edge, cp, sp),
                   det_far = edge_det(poly, far_edge, cp, sp);
      rho_min = poly.cross[near_edge] / det_near;
      rho_max = poly.cross[far_edge] / det_far;
      if (!(rho_max > rho_min && rho_min >= 0.0)) return;
      const double x_near = poly.cross[near_edge] * inv_sigma,
                   x_far = poly.cross[far_edge] * inv_sigma;
      const double inv_near = 1.0 / std::sqrt(x_near * x_near + det_near * det_near),
                   inv_far = 1.0 / std::sqrt(x_far * x_far + det_far * det_far);
      cos_near = std::abs(det_near) * inv_near, sin_near = std::abs(x_near) * inv_near;
      cos_far = std::abs(det_far) * inv_far, sin_far = std::abs(x_far) * inv_far;
    } else {
      if (!ray_interval(poly, cp, sp, inside, rho_min, rho_max)) return;
      const double t_near = rho_min * inv_sigma, t_far = rho_max * inv_sigma;
      cos_near = 1.0 / std::sqrt(1.0 + t_near * t_near);
      cos_far = 1.0 / std::sqrt(1.0 + t_far * t_far);
      sin_near = t_near * cos_near, sin_far = t_far * cos_far;
    }
    end = {true,
           sin_near,
           cos_near,
           sin_far,
           cos_far,
           rho_min * inv_sigma,
           rho_max * inv_sigma,
           quadrant_angle(sin_near, cos_near),
           quadrant_angle(sin_far, cos_far)};
  };
  std::size_t r = 0;
  while (r + 4 <= ray_count) {
    if (jobs[r].near_edge >= 0 && jobs[r + 1].near_edge >= 0 && jobs[r + 2].near_edge >= 0 &&
        jobs[r + 3].near_edge >= 0) {
      ends_by_edges4(poly, jobs + r, inv_sigma, ends + r);
      r += 4;
    } else {
      ray_ends(r++);
    }
  }
  for (; r < ray_count; ++r) ray_ends(r);
  // 3. The integral along each ray that reaches the opening, added in the rays' order.
  // The lines strictly inside each ray's range of table angles: a ray's ends cross a line only
  // where that line's circle crosses the outline, a psi break, so the rays of a cell have the
  // same (found for the first ray that reaches the opening, reused for the others). Where an end
  // lies within rounding of a line, another ray's end may lie a rounding past it: its end piece
  // then spans a signed sliver of the neighbouring interval, the same integral up to rounding.
  Vec3 moments_sum(0.0);
  std::size_t k_lo = 0, k_hi = 0, lines_cell = std::numeric_limits<std::size_t>::max();
  for (std::size_t r = 0; r < ray_count; ++r) {
    const RayEnds& end = ends[r];
    if (!end.ok) continue;
    const RayJob& job = jobs[r];
    const double cp = job.c, sp = job.s;
    const double sin_near = end.sin_near, cos_near = end.cos_near, sin_far = end.sin_far,
                 cos_far = end.cos_far;
    const double t_lo = front ? end.g_near : kPi - end.g_far,
                 t_hi = front ? end.g_far : kPi - end.g_near;
    const double c = first_copy_at_or_above(job.psi + kPi, 0.0);
    const photometry::TabularDistribution::CCell& cc = job.c_cell;
    const photometry::TabularDistribution::CPosition cpos =
        c >= cc.c0 && c <= cc.c1 ? table.c_position_in(cc, c) : table.c_position(c);
    const double tan_lo = front ? end.tan_near : end.tan_far,
                 tan_hi = front ? end.tan_far : end.tan_near;
    // Lines strictly inside (t_lo, t_hi): [k_lo, k_hi).
    if (job.cell != lines_cell) {
      k_lo = cells.first_above(t_lo), k_hi = cells.first_at_or_above(t_hi);
      lines_cell = job.cell;
    }
    if (light_vector) {
      Moments m;
      if (k_lo >= k_hi) {
        end_moments(t_lo, t_hi, tan_lo, tan_hi, cpos, m);
      } else {
        end_moments(t_lo, lines[k_lo], tan_lo, cells.line_tan[k_lo], cpos, m);
        end_moments(lines[k_hi - 1], t_hi, cells.line_tan[k_hi - 1], tan_hi, cpos, m);
        const TableGammaNode* base = cells.nodes.data();
        add_moments(base + cells.first[k_lo], base + cells.first[k_hi - 1], cpos, m);
      }
      moments_sum += job.scale * Vec3(m.radial * cp, m.radial * sp, front ? m.axial : -m.axial);
      continue;
    }
    double ray = 0.0;
    if (closed_form) {
      ray = closed_ray(t_lo, t_hi, sin_near, cos_near, sin_far, cos_far, k_lo, k_hi, cpos);
    } else if (const Ray dir{n.x * cp + n.y * sp, cp * e.rotation[0] + sp * e.rotation[1]};
               k_lo >= k_hi) {
      ray = end_cell(t_lo, t_hi, tan_lo, tan_hi, cpos, dir);
    } else {
      ray = end_cell(t_lo, lines[k_lo], tan_lo, cells.line_tan[k_lo], cpos, dir) +
            end_cell(lines[k_hi - 1], t_hi, cells.line_tan[k_hi - 1], tan_hi, cpos, dir);
      // The whole cells between: nodes precomputed per emitter (table_cells.h).
      const TableGammaNode* base = cells.nodes.data();
      ray += node_sum(base + cells.first[k_lo], base + cells.first[k_hi - 1], cpos, dir);
    }
    sum += job.scale * ray;
  }
  if (light_vector) *light_vector = (view.scale / e.area_m2) * moments_sum;
  lux = sanitize_illuminance(view.scale * sum / e.area_m2);
  return true;
}

}  // namespace

bool table_aligned_illuminance(const Emitter& e, const Vec3& point, const Receiver& receiver,
                               double& lux) {
  return table_rung(e, point, receiver, lux, nullptr);
}

bool table_light_vector(const Emitter& e, const Vec3& point, Vec3& light_vector_lx) {
  double unused = 0.0;
  Vec3 local(0.0);
  if (!table_rung(e, point, Receiver::planar(Vec3(0, 0, 1)), unused, &local)) return false;
  light_vector_lx = e.rotation * local;
  return true;
}

}  // namespace luxgrid::nearfield
