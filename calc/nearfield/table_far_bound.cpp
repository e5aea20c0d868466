#include "calc/nearfield/table_far_bound.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "calc/nearfield/emitter.h"
#include "photometry/tabular_distribution.h"

namespace luxgrid::nearfield {
namespace {

constexpr double kMapGammaStepRad = kPi / (kGammaSamples - 1);
constexpr double kMapCStepRad = kTwoPi / kCSamples;
constexpr double kInf = std::numeric_limits<double>::infinity();

// The distances tried (x D): a geometric ladder from the map's start far enough that a footprint
// of 1e-5 rad is all that is left; beyond, the near field at every distance.
constexpr double kTableLadderRatio = 1.1;
constexpr int kTableLadderRungs = 121;  // 2 D x 1.1^120 = 1.8e5 D

// Each map cell is bounded in this many parts each way (its dimmest value and the table's kinks
// near each part, not the whole cell's).
constexpr int kSubcells = 3;

// What the bound reads of the bilinear table over a set of its cells (cd, per radian of arc):
// the largest gradient, the largest second derivative along a great circle inside a cell, the
// largest slope jumps across a gamma row line (of dI/dgamma) and across a C plane (of
// dI/dC / sin gamma), what a pole cell's gradients may differ by, the dimmest value, the
// largest jump of the value itself, and the narrowest cell.
struct Stats {
  double grad_max = 0.0;
  double hess_max = 0.0;
  double kink_row = 0.0, kink_c = 0.0, kink_pole = 0.0;
  double i_min = kInf;
  double jump = 0.0;
  double dg_min = kInf, dc_min = kInf;
  bool any = false;
  void add(const Stats& o) {
    grad_max = std::max(grad_max, o.grad_max);
    hess_max = std::max(hess_max, o.hess_max);
    kink_row = std::max(kink_row, o.kink_row);
    kink_c = std::max(kink_c, o.kink_c);
    kink_pole = std::max(kink_pole, o.kink_pole);
    i_min = std::min(i_min, o.i_min);
    jump = std::max(jump, o.jump);
    dg_min = std::min(dg_min, o.dg_min);
    dc_min = std::min(dc_min, o.dc_min);
    any = any || o.any;
  }
};

// A pole row: sin gamma below this.
constexpr double kPoleSin = 1e-9;

class CellTable {
 public:
  explicit CellTable(const photometry::TabularDistribution& t) : t_(t) {
    const auto& g = t.grid();
    nc_ = g.c_rad.size();
    ng_ = g.gamma_rad.size();
    cells_.resize(nc_ * (ng_ - 1));
    for (std::size_t i = 0; i < nc_; ++i)
      for (std::size_t j = 0; j + 1 < ng_; ++j) cells_[i * (ng_ - 1) + j] = cell(i, j);
    for (double v : g.cd) peak_ = std::max(peak_, v);
  }
  double peak() const { return peak_; }
  std::size_t planes() const { return nc_; }

  // Over every table cell a cap of `radius` around the grid-frame direction (c, gamma) reaches.
  Stats over_cap(double c, double gamma, double radius) const {
    const auto& G = t_.grid().gamma_rad;
    const double lo = gamma - radius, hi = gamma + radius;
    const bool pole = lo <= 0.0 || hi >= kPi;
    // The cap's C half-width where it holds no pole: asin(sin r / sin gamma).
    const double half_c = pole ? kPi : std::asin(std::min(1.0, std::sin(radius) / std::sin(gamma)));
    Stats s;
    std::vector<std::size_t>& cols = cols_scratch_;
    cols.clear();
    if (nc_ == 1 || half_c >= kPi) {
      for (std::size_t i = 0; i < nc_; ++i) cols.push_back(i);
    } else {
      for (std::size_t i = 0; i < nc_; ++i) {
        const double c0 = c_at(i), c1 = c_at(i + 1);
        for (double shift : {-kTwoPi, 0.0, kTwoPi})
          if (c0 + shift <= c + half_c && c1 + shift >= c - half_c) {
            cols.push_back(i);
            break;
          }
      }
    }
    for (std::size_t j = 0; j + 1 < ng_; ++j) {
      if (G[j + 1] < lo || G[j] > hi) continue;
      for (std::size_t i : cols) s.add(cells_[i * (ng_ - 1) + j]);
    }
    // Beyond the table's first or last row the intensity is 0: a jump by that row's value and a
    // slope jump by the slope next to it, where the row is not a pole.
    auto edge = [&](std::size_t row) {
      s.i_min = 0.0;
      s.kink_row = std::max(s.kink_row, s.grad_max);
      for (std::size_t i : cols) s.jump = std::max(s.jump, t_.grid().at(i, row));
    };
    if (lo < G.front() && G.front() > 1e-9) edge(0);
    if (hi > G.back() && G.back() < kPi - 1e-9) edge(ng_ - 1);
    return s;
  }

 private:
  double v(std::size_t i, std::size_t j) const { return t_.grid().at(i % nc_, j); }
  // Plane i's C, unwrapped past the last plane (i < 2 nc).
  double c_at(std::size_t i) const {
    const auto& C = t_.grid().c_rad;
    return i < nc_ ? C[i] : C[i - nc_] + kTwoPi;
  }
  // dI/dgamma of gamma cell j on plane i, and dI/dC of C cell i on row j.
  double slope_g(std::size_t i, std::size_t j) const {
    const auto& G = t_.grid().gamma_rad;
    return (v(i, j + 1) - v(i, j)) / (G[j + 1] - G[j]);
  }
  double slope_c(std::size_t i, std::size_t j) const {
    return (v(i + 1, j) - v(i, j)) / (c_at(i + 1) - c_at(i));
  }

  Stats cell(std::size_t i, std::size_t j) const {
    const auto& G = t_.grid().gamma_rad;
    const std::size_t i1 = nc_ == 1 ? i : i + 1;
    const double v00 = v(i, j), v01 = v(i, j + 1), v10 = v(i1, j), v11 = v(i1, j + 1);
    const double g0 = G[j], g1 = G[j + 1], dg = g1 - g0;
    Stats s;
    s.any = true;
    s.i_min = std::min({v00, v01, v10, v11});
    s.dg_min = dg;
    const double sin0 = std::sin(g0), sin1 = std::sin(g1), sin_lo = std::min(sin0, sin1);
    const bool pole_cell = sin_lo <= kPoleSin;
    const double cot =
        pole_cell ? 0.0 : std::max(std::abs(std::cos(g0) / sin0), std::abs(std::cos(g1) / sin1));
    // Bilinear in (C, gamma): dI/dgamma is linear in C across the cell, dI/dC linear in gamma.
    const double g_abs = std::max(std::abs(v01 - v00), std::abs(v11 - v10)) / dg;
    // The factor 1 / sin gamma of the C slope over the cell; at a pole row the C differences
    // vanish (the row is averaged, tabular_distribution.h; else a jump, below) and the slope
    // grows from there as t / sin(t dgamma) <= 1 / sin dgamma.
    const double inv_sin =
        pole_cell ? 1.0 / std::max(std::sin(std::min(dg, kPi - 1e-3)), 1e-3) : 1.0 / sin_lo;
    double c_abs = 0.0;
    if (nc_ > 1) {
      const double dc = c_at(i + 1) - c_at(i);
      s.dc_min = dc;
      c_abs = std::max(std::abs(v10 - v00), std::abs(v11 - v01)) / dc * inv_sin;
      if (pole_cell) s.jump = std::abs(sin0 <= kPoleSin ? v10 - v00 : v11 - v01);
      // Slope jumps of dI/dC across the cell's two planes (plane i between C cells i - 1 and i).
      for (std::size_t plane : {i, i + 1})
        for (std::size_t row : {j, j + 1}) {
          const double k =
              std::abs(slope_c(plane % nc_, row) - slope_c((plane + nc_ - 1) % nc_, row));
          s.kink_c = std::max(s.kink_c, k * inv_sin);
        }
      // The second derivative along a great circle (covariant, per radian^2): the twist over
      // sin gamma and the sphere's cot gamma terms; d2I/dgamma2 = d2I/dC2 = 0 (bilinear).
      const double f = std::abs(v11 - v10 - v01 + v00) / (dg * dc);
      if (!pole_cell) s.hess_max = 2.0 * (f / sin_lo + cot * c_abs) + cot * g_abs;
    } else if (!pole_cell) {
      s.hess_max = cot * g_abs;
    }
    // Slope jumps of dI/dgamma across the cell's two row lines (inside the table).
    for (std::size_t plane : {i, i1}) {
      if (j > 0)
        s.kink_row = std::max(s.kink_row, std::abs(slope_g(plane, j) - slope_g(plane, j - 1)));
      if (j + 2 < ng_)
        s.kink_row = std::max(s.kink_row, std::abs(slope_g(plane, j + 1) - slope_g(plane, j)));
    }
    s.grad_max = std::hypot(g_abs, c_abs);
    // A pole cell: two of its gradients differ by at most twice the largest (the cone a bilinear
    // table makes at the pole), charged as one kink.
    if (pole_cell) s.kink_pole = 2.0 * s.grad_max;
    return s;
  }

  const photometry::TabularDistribution& t_;
  std::size_t nc_ = 0, ng_ = 0;
  std::vector<Stats> cells_;
  double peak_ = 0.0;
  mutable std::vector<std::size_t> cols_scratch_;
};

// The bilinear table behind a distribution, and the matrix taking luminaire directions into its
// grid; null where there is none.
const photometry::TabularDistribution* bilinear_table(const Emitter& e) {
  const photometry::TableView view = e.distribution->table_view();
  const photometry::TabularDistribution* t =
      view.table ? view.table
                 : dynamic_cast<const photometry::TabularDistribution*>(e.distribution.get());
  if (!t || t->interpolation() != photometry::Interpolation::bilinear) return nullptr;
  if (t->grid().gamma_rad.size() < 2) return nullptr;
  return t;
}

// The opening as the bound sees it (x D): its circumradius about the centroid and the root mean
// square distance of its points from the centroid (exact, from the fan of triangles).
struct OpeningSize {
  double rho, rms;
};

// The table's part of the error over `region`, relative to `den` (cd), at distance d (x D) with
// the footprint's half-angle delta = asin(rho / d); `pole_distance` (rad): how near a pole the
// footprint of a direction of the part can reach.
// The remainder R(x) = I(w_x) - I(w_c) - L . (w_x - w_c): along the great-circle arc from w_c to
// w_x its slope changes by the slope jumps of the lines the arc crosses (each line once: crossing
// back returns to the same cell; row lines at most delta / dgamma + 1, C planes the arc's C span
// over the narrowest spacing, plus one), by the second derivative inside cells and by the turn of
// the tangent plane (G delta), and never by more than 2 G in all. A line at angle t from w_c adds
// K (s . n - t)+ <= K (s . n)+ at the footprint's point s = w_x - w_c, whose mean over the opening
// is at most half the mean |s| plus the mean of s (second order, <= 2 delta^2): so the kinks cost
// K (s1 / 2 + delta^2), s1 = rms / (d - rho) >= the mean angle, and the second derivative
// (H + G delta) s1^2 / 2. The weight g of each point (receivers at most 75 degrees from facing)
// is within 1 + 25 delta of its mean.
double table_part(const Stats& region, const OpeningSize& o, double d_over_D, double delta,
                  double pole_distance, std::size_t planes, double den) {
  if (!region.any) return region.jump / den;  // beyond the table: 0, up to the edge's jump
  const double s1 = o.rms / std::max(d_over_D - o.rho, 1e-9);
  const double rows = std::floor(delta / region.dg_min) + 1.0;
  double c_span = kPi;
  if (pole_distance > delta)
    c_span = 2.0 * std::asin(std::min(1.0, std::sin(delta) / std::sin(pole_distance)));
  const double cs =
      planes > 1 ? std::min(static_cast<double>(planes), std::floor(c_span / region.dc_min) + 1.0)
                 : 0.0;
  const double kinks = rows * region.kink_row + cs * region.kink_c + region.kink_pole;
  const double remainder =
      (1.0 + 25.0 * delta) *
      std::min(2.0 * region.grad_max * s1,
               kinks * (0.5 * s1 + 2.0 * delta * delta) +
                   0.5 * (region.hess_max + region.grad_max * delta) * s1 * s1);
  return (remainder + region.grad_max * kFirstOrderKappa * delta * delta + region.jump) / den;
}

// What the part of a map cell from (g0, c0) (in samples) spanning 1 / kSubcells of it each way
// needs (x D): the first rung of the ladder from which table_part is within `b` for every
// direction in it.
float subcell_need(const CellTable& cells, const glm::dmat3& to_grid, double g0, double c0,
                   const OpeningSize& o, double floor_cd, double b) {
  constexpr double step = 1.0 / kSubcells;
  // Its directions lie within rc of its centre (corners and edge midpoints; the C edges are
  // small circles, bulging a hair beyond their chord: the margin).
  const Vec3 centre = photometry::direction_of((c0 + 0.5 * step) * kMapCStepRad,
                                               (g0 + 0.5 * step) * kMapGammaStepRad);
  double rc = 0.0;
  for (double fg : {0.0, 0.5, 1.0})
    for (double fc : {0.0, 0.5, 1.0})
      rc = std::max(
          rc, angle_between(centre, photometry::direction_of((c0 + fc * step) * kMapCStepRad,
                                                             (g0 + fg * step) * kMapGammaStepRad)));
  rc += 0.1 * kDegToRad;
  const photometry::PhotometricAngles a = photometry::angles_of(to_grid * centre);
  const Stats here = cells.over_cap(a.c, a.gamma, rc);
  const double den = std::max(std::isfinite(here.i_min) ? here.i_min : 0.0, floor_cd);
  auto passes = [&](int k) {
    const double d_over_D = kLadderStart * std::pow(kTableLadderRatio, k);
    const double delta = std::asin(std::min(1.0, o.rho / d_over_D));
    const double radius = rc + delta;
    const Stats region = cells.over_cap(a.c, a.gamma, radius);
    const double pole_distance = std::min(a.gamma - radius, kPi - a.gamma - radius) + delta;
    return table_part(region, o, d_over_D, delta, pole_distance, cells.planes(), den) <= b;
  };
  if (!passes(kTableLadderRungs - 1)) return kNearEverywhere;
  int lo = -1, hi = kTableLadderRungs - 1;  // lo fails (or none), hi passes
  if (passes(0))
    hi = 0;
  else
    lo = 0;
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    (passes(mid) ? hi : lo) = mid;
  }
  return static_cast<float>(kLadderStart * std::pow(kTableLadderRatio, hi));
}

}  // namespace

std::vector<float> table_far_bound_over_D(const Emitter& e, double budget,
                                          const std::vector<float>& wanted) {
  const photometry::TabularDistribution* table = bilinear_table(e);
  if (!table || e.is_point() || !(e.largest_dimension_m > 0.0)) return {};
  const CellTable cells(*table);
  OpeningSize o{0.0, 0.0};
  double second_moment = 0.0;  // integral of |x - c|^2 dA over the fan from the centroid (m^4)
  for (std::size_t k = 0; k < e.vertices.size(); ++k) {
    const Vec3 p = e.vertices[k] - e.centroid;
    const Vec3 q = e.vertices[(k + 1) % e.vertices.size()] - e.centroid;
    const double area = 0.5 * glm::length(glm::cross(p, q));
    second_moment += area / 6.0 * (glm::dot(p, p) + glm::dot(q, q) + glm::dot(p, q));
    o.rho = std::max(o.rho, glm::length(p));
  }
  o.rho /= e.largest_dimension_m;
  o.rms = std::sqrt(second_moment / e.area_m2) / e.largest_dimension_m;
  const glm::dmat3 to_grid = table->has_frame() ? table->table_from_luminaire() : glm::dmat3(1.0);
  const double floor_cd = kDimFloor * cells.peak();
  // Relative to the near value: |far - near| <= b far is within b / (1 - b) of near.
  const double b = budget / (1.0 + budget);

  const int ncell = (kGammaSamples - 1) * kCSamples;
  std::vector<float> cell_over_D(ncell, 0.0f);
  auto sample_wanted = [&](int g, int c) { return wanted[g * kCSamples + c % kCSamples] > 0.0f; };
  for (int g = 0; g + 1 < kGammaSamples; ++g)
    for (int c = 0; c < kCSamples; ++c) {
      if (!(sample_wanted(g, c) || sample_wanted(g, c + 1) || sample_wanted(g + 1, c) ||
            sample_wanted(g + 1, c + 1)))
        continue;
      // The cell in kSubcells x kSubcells parts, each with its own dimmest value and its own
      // neighbourhood of the table: the cell's need is the largest of theirs.
      float need = 0.0f;
      for (int sg = 0; sg < kSubcells; ++sg)
        for (int sc = 0; sc < kSubcells; ++sc)
          need =
              std::max(need, subcell_need(cells, to_grid, g + static_cast<double>(sg) / kSubcells,
                                          c + static_cast<double>(sc) / kSubcells, o, floor_cd, b));
      cell_over_D[g * kCSamples + c] = need;
    }
  // A sample carries the largest need of the (up to four) cells it is a corner of, so that the
  // map's interpolation (in 1 / d, between a cell's corners) never asks less inside a cell.
  std::vector<float> out(kGammaSamples * kCSamples, 0.0f);
  for (int g = 0; g < kGammaSamples; ++g)
    for (int c = 0; c < kCSamples; ++c) {
      if (!(wanted[g * kCSamples + c] > 0.0f)) continue;
      float v = 0.0f;
      for (int cg : {g - 1, g})
        for (int cc : {c - 1, c}) {
          if (cg < 0 || cg + 1 >= kGammaSamples) continue;
          v = std::max(v, cell_over_D[cg * kCSamples + (cc + kCSamples) % kCSamples]);
        }
      out[g * kCSamples + c] = v;
    }
  return out;
}

}  // namespace luxgrid::nearfield
