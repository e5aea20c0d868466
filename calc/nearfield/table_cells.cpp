#include "calc/nearfield/table_cells.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace luxgrid::nearfield {
namespace {

constexpr double kHalfPi = 0.5 * kPi;

// Gauss nodes of one piece [p0, p1] of gamma' (receiver-side angle, < pi / 2).
void append_piece(const photometry::TabularDistribution& table, double p0, double p1, bool back,
                  std::vector<TableGammaNode>& out) {
  const double w = 0.5 * (p1 - p0);
  const GaussPair g = gauss_pair(p0, p1);
  for (int k = 0; k < 2; ++k) {
    const double gp = k == 0 ? g.x_lo : g.x_hi, s = k == 0 ? g.s_lo : g.s_hi,
                 c = k == 0 ? g.c_lo : g.c_hi;
    TableGammaNode node{back ? kPi - gp : gp, s, c, w * s / c};
    std::size_t j = 0;
    if (table.gamma_cell(node.gamma, j, node.tg)) node.row = static_cast<long>(j);
    out.push_back(node);
  }
}

}  // namespace

void append_gamma_nodes(const photometry::TabularDistribution& table, double a, double b,
                        double tan_a, double tan_b, std::vector<TableGammaNode>& out) {
  if (!(b - a > 1e-12)) return;
  const bool back = a >= kHalfPi;
  const double lo = back ? kPi - b : a, hi = back ? kPi - a : b;  // gamma' interval
  const int wide = pieces_of_at_most((hi - lo) / kTableMaxGammaCell);
  for (int k = 0; k < wide; ++k) {
    const double p0 = lo + (hi - lo) * k / wide,
                 p1 = k + 1 == wide ? hi : lo + (hi - lo) * (k + 1) / wide;
    // |tan| at the piece's ends in gamma' order (the caller's values are in table order).
    const double known_lo = back ? tan_b : tan_a, known_hi = back ? tan_a : tan_b;
    const double t0 = k == 0 && known_lo >= 0.0 ? known_lo : std::tan(p0);
    const double t1 = k + 1 == wide && known_hi >= 0.0 ? known_hi : std::tan(p1);
    if (!(t0 > 0.0) || !(t1 > kTableTanRatio * t0) || !std::isfinite(t1)) {
      append_piece(table, p0, p1, back, out);
      continue;
    }
    const int pieces = pieces_of_at_most(std::log(t1 / t0) / std::log(kTableTanRatio));
    const double ratio = std::pow(t1 / t0, 1.0 / pieces);
    double q0 = p0, t = t0;
    for (int q = 1; q <= pieces; ++q) {
      t *= ratio;
      const double q1 = q == pieces ? p1 : std::atan(t);
      append_piece(table, q0, q1, back, out);
      q0 = q1;
    }
  }
}

std::shared_ptr<const TableGammaCells> make_table_gamma_cells(
    const photometry::TabularDistribution& table) {
  auto cells = std::make_shared<TableGammaCells>();
  cells->table = &table;
  cells->lines = table.grid().gamma_rad;
  if (std::find(cells->lines.begin(), cells->lines.end(), kHalfPi) == cells->lines.end()) {
    cells->lines.push_back(kHalfPi);
    std::sort(cells->lines.begin(), cells->lines.end());
  }
  const std::vector<double>& L = cells->lines;
  for (double g : L)
    cells->line_tan.push_back(g == kHalfPi ? std::numeric_limits<double>::infinity()
                                           : std::abs(std::tan(g)));
  cells->first.assign(L.size(), 0);
  for (std::size_t k = 0; k + 1 < L.size(); ++k) {
    cells->first[k] = static_cast<int>(cells->nodes.size());
    // A cell touching pi / 2 is never crossed whole by a ray (the receiver is off the plane),
    // and tan is unbounded there: the rung integrates it as an end cell.
    if (L[k] != kHalfPi && L[k + 1] != kHalfPi)
      append_gamma_nodes(table, L[k], L[k + 1], cells->line_tan[k], cells->line_tan[k + 1],
                         cells->nodes);
  }
  cells->first.back() = static_cast<int>(cells->nodes.size());

  for (double g : L) {
    cells->line_sin.push_back(g == kHalfPi ? 1.0 : std::sin(g));
    cells->line_cos.push_back(g == kHalfPi ? 0.0 : std::cos(g));
  }
  for (double c : table.grid().c_rad) {
    cells->c_break_cos.push_back(std::cos(c - kPi));
    cells->c_break_sin.push_back(std::sin(c - kPi));
  }
  const std::vector<double>& G = table.grid().gamma_rad;
  for (std::size_t j = 0; j + 1 < G.size(); ++j)
    cells->inv_row_width.push_back(1.0 / (G[j + 1] - G[j]));
  cells->interval_row.assign(L.size(), -1);
  std::vector<double> w_lo(L.size(), 0.0), w_hi(L.size(), 0.0);
  for (std::size_t k = 0; k + 1 < L.size(); ++k) {
    std::size_t j = 0;
    double tg = 0.0;
    if (!table.gamma_cell(0.5 * (L[k] + L[k + 1]), j, tg) || G.size() < 2) continue;
    cells->interval_row[k] = static_cast<long>(j);
    // The integral is linear in (I at row j, I at row j + 1): its weights are its values at
    // (1, 0) and (0, 1).
    const auto integral = [&](double i0, double i1) {
      return linear_sin_integral(L[k], cells->line_sin[k], cells->line_cos[k], L[k + 1],
                                 cells->line_sin[k + 1], cells->line_cos[k + 1], G[j],
                                 cells->inv_row_width[j], i0, i1);
    };
    w_lo[k] = integral(1.0, 0.0);
    w_hi[k] = integral(0.0, 1.0);
  }
  cells->planes = table.grid().c_rad.size();
  cells->plane_sums.assign(cells->planes * L.size(), 0.0);
  for (std::size_t i = 0; i < cells->planes; ++i) {
    const photometry::TabularDistribution::CPosition plane{i, 0.0};
    double* sums = cells->plane_sums.data() + i * L.size();
    for (std::size_t k = 0; k + 1 < L.size(); ++k) {
      double interval = 0.0;  // outside the table's gamma range: intensity zero
      if (const long row = cells->interval_row[k]; row >= 0) {
        const std::size_t j = static_cast<std::size_t>(row);
        interval = w_lo[k] * table.row_value(plane, j) + w_hi[k] * table.row_value(plane, j + 1);
      }
      sums[k + 1] = sums[k] + interval;
    }
  }
  // The buckets of first_above / first_at_or_above: as wide as the narrowest gap between lines.
  double gap = kPi;
  for (std::size_t k = 0; k + 1 < L.size(); ++k) gap = std::min(gap, L[k + 1] - L[k]);
  const std::size_t buckets = std::min<std::size_t>(
      4096, static_cast<std::size_t>(std::ceil(kPi / std::max(gap, kPi / 4096))) + 1);
  cells->inv_bucket = static_cast<double>(buckets - 1) / kPi;
  for (std::size_t b = 0; b < buckets; ++b)
    cells->bucket_first.push_back(static_cast<std::size_t>(
        std::lower_bound(L.begin(), L.end(), static_cast<double>(b) / cells->inv_bucket) -
        L.begin()));
  return cells;
}

}  // namespace luxgrid::nearfield
