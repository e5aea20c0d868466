#pragma once
// The gamma side of the table rung's cells (calc/nearfield/table_cubature.cpp), computed once per
// emitter: every cell between two gamma lines of a table, split where it is wide or where
// tan(gamma') grows fast, with its Gauss-Legendre nodes and their sines and cosines. They do not
// depend on the receiver, so a ray of the rung only computes trigonometry for its two end cells.
#include <cmath>
#include <memory>
#include <vector>

#include "photometry/tabular_distribution.h"
#include "util/robust_math.h"

namespace luxgrid::nearfield {

// Largest gamma width of a cell (rad, 5 deg) when the table has no line inside it: the weight
// tan(gamma') cos_r must still be resolved.
inline constexpr double kTableMaxGammaCell = 5.0 * kPi / 180.0;
// Towards the emitter plane (gamma' -> 90 deg) tan(gamma') grows without bound; a cell over which
// it grows by more than this ratio is cut at equal ratios, so the weight is nearly linear in
// each piece.
inline constexpr double kTableTanRatio = 1.25;

// The table rung's rule on every cell: 2-point Gauss-Legendre, nodes kGauss2Node and
// 1 - kGauss2Node on [0, 1], weights 1/2. Exact for cubics, so for a bilinear cell times a smooth
// weight the error is the weight's fourth derivative times the cell size^4 / 4320.
inline constexpr double kGauss2Node = 0.21132486540518711775;  // (1 - 1/sqrt(3)) / 2

// The angles, sines and cosines of the two Gauss nodes a + (b - a) kGauss2Node and
// a + (b - a) (1 - kGauss2Node) = m -+ delta (m the midpoint): one sin and cos of m, and delta's
// by their Taylor series where |delta| <= kGaussPairSeriesMax (the table rung's cells: at most
// 7.5 degrees wide in psi, 5 in gamma, so |delta| <= 0.038), exact to rounding: the first omitted
// terms, delta^9 / 9! and delta^10 / 10!, are below 1e-16 of the kept ones. Wider: the library.
inline constexpr double kGaussPairSeriesMax = 0.05;
struct GaussPair {
  double x_lo, s_lo, c_lo;  // node towards a: angle, sin, cos
  double x_hi, s_hi, c_hi;  // node towards b
  double x_mid;             // the midpoint
};
// With the midpoint's sine and cosine when the caller knows them (the table rung's psi cells
// take them from their ends' directions), else computed here.
inline GaussPair gauss_pair(double a, double b, double sin_mid = 2.0, double cos_mid = 2.0) {
  const double m = a + 0.5 * (b - a), delta = (b - a) * (0.5 - kGauss2Node);
  GaussPair g{m - delta, 0.0, 0.0, m + delta, 0.0, 0.0, m};
  if (!(std::abs(delta) <= kGaussPairSeriesMax)) {
    g.s_lo = std::sin(g.x_lo), g.c_lo = std::cos(g.x_lo);
    g.s_hi = std::sin(g.x_hi), g.c_hi = std::cos(g.x_hi);
    return g;
  }
  const double d2 = delta * delta;
  // The factorials' reciprocals are constants: multiplying by them keeps divisions (each a
  // dozen cycles, one after the other here) off the psi cells' chain of dependent operations.
  const double sd =
      delta * (1.0 - d2 * (1.0 / 6) * (1.0 - d2 * (1.0 / 20) * (1.0 - d2 * (1.0 / 42))));
  const double cd =
      1.0 - d2 * 0.5 * (1.0 - d2 * (1.0 / 12) * (1.0 - d2 * (1.0 / 30) * (1.0 - d2 * (1.0 / 56))));
  const bool given = sin_mid <= 1.0;
  const double sm = given ? sin_mid : std::sin(m), cm = given ? cos_mid : std::cos(m);
  g.s_lo = sm * cd - cm * sd, g.c_lo = cm * cd + sm * sd;
  g.s_hi = sm * cd + cm * sd, g.c_hi = cm * cd - sm * sd;
  return g;
}

struct TableGammaNode {
  double gamma;       // table angle, rad
  double sin_g;       // sin(gamma) = sin(gamma')
  double abs_cos_g;   // |cos(gamma)| = cos(gamma') on the receiver's side
  double weight_tan;  // Gauss weight (in rad) x tan(gamma')
  // The table's gamma cell of `gamma` (TabularDistribution::gamma_cell); row < 0: outside the
  // table's gamma range, intensity zero.
  long row = -1;
  double tg = 0.0;
};

struct TableGammaCells {
  const photometry::TabularDistribution* table = nullptr;  // built from this table
  std::vector<double> lines;  // the table's gamma lines and pi / 2, ascending, rad
  std::vector<double>
      line_tan;            // |tan| of each line (of gamma' = gamma or pi - gamma); inf at pi / 2
  std::vector<int> first;  // the nodes of cell k (lines[k], lines[k + 1]) are
                           // nodes[first[k]] .. nodes[first[k + 1] - 1]
  std::vector<TableGammaNode> nodes;

  // For the closed form along a ray (bilinear tables, receivers facing the opening's axis;
  // table_cubature.cpp): sin and cos of each line's table angle, and per interval k
  // (lines[k], lines[k + 1]) the table's gamma row j holding it (-1 outside the table's range:
  // intensity zero).
  std::vector<double> line_sin, line_cos;
  std::vector<long> interval_row;
  // The exact integral of I sin(gamma) over whole intervals along one C plane of the table, as
  // running sums: plane_sums[i * lines.size() + k] is the sum over intervals k' < k on plane i.
  // On a bilinear table I is linear in C between two planes, and so is the integral: a ray's
  // whole intervals [k_begin, k_end) cost two differences and one interpolation
  // (whole_intervals), not two table reads per interval. The sums are of non-negative terms, so
  // a difference loses at most (number of intervals) x 1e-16 of the plane's whole sum.
  std::vector<double> plane_sums;
  std::size_t planes = 0;
  double whole_intervals(const photometry::TabularDistribution::CPosition& c, std::size_t k_begin,
                         std::size_t k_end) const {
    const std::size_t n = lines.size();
    const double* p0 = plane_sums.data() + c.i * n;
    const double s0 = p0[k_end] - p0[k_begin];
    if (planes == 1) return s0;
    const double* p1 = plane_sums.data() + (c.i + 1 < planes ? c.i + 1 : 0) * n;
    return s0 + c.tc * ((p1[k_end] - p1[k_begin]) - s0);
  }
  // 1 / (width of the table's gamma row j), per row.
  std::vector<double> inv_row_width;
  // Per C plane of the table (C ascending in [0, 2 pi), size 1: none): the direction of the psi
  // break it makes, psi = C - pi, as (cos, sin), so a break needs no cosine of its own.
  std::vector<double> c_break_cos, c_break_sin;

  // Where an angle falls among the lines, as std::upper_bound (first line > t) and
  // std::lower_bound (first line >= t) give it, from a bucket of width at most the narrowest gap
  // between lines (so the bucket's first line is at most one step from the answer) instead of a
  // binary search: two a ray.
  std::size_t first_above(double t) const { return scan(t, false); }
  std::size_t first_at_or_above(double t) const { return scan(t, true); }
  double inv_bucket = 0.0;
  std::vector<std::size_t> bucket_first;  // first line >= the bucket's lower end

 private:
  std::size_t scan(double t, bool at_or_above) const {
    const double b = t * inv_bucket;
    const std::size_t last_bucket = bucket_first.size() - 1, count = lines.size();
    const double* line = lines.data();
    std::size_t k = b >= 0.0 ? bucket_first[std::min(static_cast<std::size_t>(b), last_bucket)] : 0;
    while (k > 0 && (at_or_above ? line[k - 1] >= t : line[k - 1] > t)) --k;
    while (k < count && (at_or_above ? line[k] < t : line[k] <= t)) ++k;
    return k;
  }
};

// The exact integral over table angles [a, b] (one gamma row j of the table, rows at g0 < g1,
// inv_dg = 1 / (g1 - g0)) of I(gamma) sin(gamma) d gamma, I linear in gamma from i0 at g0 to i1 at
// g1: the closed form of the table rung's gamma integral for a receiver facing the axis
// (docs/nearfield.md). sa, ca, sb, cb: sin and cos of a and b.
inline double linear_sin_integral(double a, double sa, double ca, double b, double sb, double cb,
                                  double g0, double inv_dg, double i0, double i1) {
  // integral of sin = ca - cb; of (gamma - g0) sin(gamma): [sin(gamma) - (gamma - g0) cos(gamma)]
  const double slope = (i1 - i0) * inv_dg;
  return i0 * (ca - cb) + slope * ((sb - (b - g0) * cb) - (sa - (a - g0) * ca));
}

// Appends the 2-point Gauss-Legendre nodes of the table-angle interval [a, b] (on one side of
// pi / 2), split by kTableMaxGammaCell and kTableTanRatio, each with its cell in `table`.
// tan_a, tan_b: |tan| at a and b when the caller knows them (else negative: computed here).
void append_gamma_nodes(const photometry::TabularDistribution& table, double a, double b,
                        double tan_a, double tan_b, std::vector<TableGammaNode>& out);

std::shared_ptr<const TableGammaCells> make_table_gamma_cells(
    const photometry::TabularDistribution& table);

}  // namespace luxgrid::nearfield
