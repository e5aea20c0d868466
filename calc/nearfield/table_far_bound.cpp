#include "calc/nearfield/table_far_bound.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <tbb/enumerable_thread_specific.h>

#include "calc/nearfield/emitter.h"
#include "photometry/tabular_distribution.h"
#include "util/ordered_tasks.h"

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
// largest slope jumps across the gamma row lines (of dI/dgamma) and the C planes (of
// dI/dC / sin gamma) the footprint can reach, what a pole cell's gradients may differ by, the
// dimmest value, the largest jump of the value itself, and the narrowest cell.
struct Stats {
  double grad_max = 0.0;
  double grad_g_max = 0.0, grad_c_max = 0.0;  // its parts along gamma and along C
  double hess_max = 0.0;
  double kink_row = 0.0, kink_c = 0.0, kink_pole = 0.0;
  double i_min = kInf;
  double jump = 0.0;
  double dg_min = kInf, dc_min = kInf;
  bool any = false;
  void add(const Stats& o) {
    grad_max = std::max(grad_max, o.grad_max);
    grad_g_max = std::max(grad_g_max, o.grad_g_max);
    grad_c_max = std::max(grad_c_max, o.grad_c_max);
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

// A table cell: its own stats (no kinks) and the slope jumps on its four sides, each charged
// only where the footprint reaches that side (a kink the footprint does not straddle adds
// nothing to the remainder: docs/nearfield.md, "What the map bounds and what it measures").
struct CellStats {
  Stats inside;
  double kink_row_lo = 0.0, kink_row_hi = 0.0;  // row lines j and j + 1
  double kink_c_lo = 0.0, kink_c_hi = 0.0;      // C planes i and i + 1
};

// A table line left out of a bound: the footprint is known not to reach it (-1: none).
struct Excluded {
  long row = -1, plane = -1;
};

// A pole row: sin gamma below this.
constexpr double kPoleSin = 1e-9;

// The first i in [0, n) where `holds` fails, for a predicate that holds on a prefix (n if none):
// from `near` outward in steps that double, then by bisection (the answer is one, wherever the
// search starts; a start near it takes a few steps).
template <class Predicate>
std::size_t first_failing(std::size_t n, std::size_t near, Predicate holds) {
  std::size_t lo = 0, hi = n;  // the answer lies in [lo, hi]; holds at lo - 1, fails at hi < n
  if (near < n) {
    if (holds(near)) {
      lo = near + 1;
      for (std::size_t step = 1; lo < n; step *= 2) {
        const std::size_t probe = std::min(n - 1, lo + step - 1);
        if (!holds(probe)) {
          hi = probe;
          break;
        }
        lo = probe + 1;
      }
    } else {
      hi = near;
      for (std::size_t step = 1; hi > 0; step *= 2) {
        const std::size_t probe = hi > step ? hi - step : 0;
        if (holds(probe)) {
          lo = probe + 1;
          break;
        }
        hi = probe;
      }
    }
  }
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (holds(mid))
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo;
}

class CellTable {
 public:
  explicit CellTable(const photometry::TabularDistribution& t) : t_(t) {
    const auto& g = t.grid();
    nc_ = g.c_rad.size();
    ng_ = g.gamma_rad.size();
    for (std::size_t i = 0; i < 2 * nc_; ++i)
      c_unwrapped_.push_back(i < nc_ ? g.c_rad[i] : g.c_rad[i - nc_] + kTwoPi);
    cells_.resize(nc_ * (ng_ - 1));
    for (std::size_t i = 0; i < nc_; ++i)
      for (std::size_t j = 0; j + 1 < ng_; ++j) cells_[i * (ng_ - 1) + j] = cell(i, j);
    for (double v : g.cd) peak_ = std::max(peak_, v);
  }
  double peak() const { return peak_; }
  std::size_t planes() const { return nc_; }
  std::size_t rows() const { return ng_; }
  double row_rad(std::size_t j) const { return t_.grid().gamma_rad[j]; }
  double plane_rad(std::size_t i) const { return t_.grid().c_rad[i]; }

  // The dimmest value of the bilinear table over the grid-frame rectangle [c0, c1] x [g0, g1]
  // (c1 - c0 below 2 pi): on each cell's part of it the bilinear value is least at a corner of
  // that part, so at the rectangle's corners, where its sides cross the table's lines, or at a
  // table node inside.
  double min_over_rect(double c0, double c1, double g0, double g1) const {
    const auto& G = t_.grid().gamma_rad;
    std::vector<double> cs{c0, c1}, gs{g0, g1};
    for (std::size_t i = 0; i < 2 * nc_; ++i)
      for (double shift : {-kTwoPi, 0.0})
        if (c_at(i) + shift > c0 && c_at(i) + shift < c1) cs.push_back(c_at(i) + shift);
    for (double g : G)
      if (g > g0 && g < g1) gs.push_back(g);
    double m = kInf;
    for (double c : cs)
      for (double g : gs) m = std::min(m, value(c, g));
    return m;
  }

  // The C half-width of a cap of `radius` around gamma (`sin_gamma` = sin gamma) where it holds
  // no pole: asin(sin r / sin gamma); pi where it holds one.
  static double cap_half_c(double gamma, double sin_gamma, double radius) {
    const bool pole = gamma - radius <= 0.0 || gamma + radius >= kPi;
    return pole ? kPi : std::asin(std::min(1.0, std::sin(radius) / sin_gamma));
  }

  // Whether over_cap(c, gamma, radius, half_c, cols, ex) may charge a slope jump of the line
  // `ex`: a row line within the cap's range of gamma, or a C plane the cap reaches. Where it does
  // not, over_cap gives the same with `ex` left out as with it.
  bool cap_reaches_line(double c, double gamma, double radius, double half_c, Excluded ex) const {
    if (ex.row >= 0) {
      const double g = t_.grid().gamma_rad[ex.row];
      if (g >= gamma - radius && g <= gamma + radius) return true;
    }
    return ex.plane >= 0 && cap_reaches_plane(c, half_c, ex.plane);
  }

  // A C cell a cap reaches, and whether the cap reaches (and the bound charges) the slope jumps
  // of its two planes.
  struct Col {
    std::size_t i;
    bool plane_lo, plane_hi;
  };
  // The C cells of one cap: the caller's, one per thread, so that map cells can be bounded in
  // parallel. With where the searches for the last cap ended, to start the next one's from
  // (a thread's caps follow each other around one direction).
  struct Cols {
    std::vector<Col> list;
    std::array<std::size_t, 3> begin_near{}, end_near{};  // per shift of a turn
    std::size_t row_near = 0;
  };

  // Over every table cell a cap of `radius` around the grid-frame direction (c, gamma) reaches
  // (its C half-width `half_c`, cap_half_c's); a row line's or C plane's slope jump only where the
  // cap reaches the line, and never of the line `ex`.
  Stats over_cap(double c, double gamma, double radius, double half_c, Cols& cols,
                 Excluded ex = {}) const {
    const auto& G = t_.grid().gamma_rad;
    const double lo = gamma - radius, hi = gamma + radius;
    auto reaches_plane = [&](std::size_t i) { return cap_reaches_plane(c, half_c, i); };
    cols.list.clear();
    auto add_col = [&](std::size_t i) {
      const std::size_t i1 = i + 1 == nc_ ? 0 : i + 1;
      cols.list.push_back({i, static_cast<long>(i) != ex.plane && reaches_plane(i),
                           static_cast<long>(i1) != ex.plane && reaches_plane(i1)});
    };
    if (nc_ == 1 || half_c >= kPi) {
      for (std::size_t i = 0; i < nc_; ++i) add_col(i);
    } else {
      // The C cells [c_at(i), c_at(i + 1)] meeting [c - half_c, c + half_c], that interval also
      // shifted by a turn either way: for each shift a run of i (c_at ascends), found by
      // bisection; the runs in ascending order, each cell once.
      std::array<std::pair<std::size_t, std::size_t>, 3> runs;
      for (int n = 0; n < 3; ++n) {
        const double shift = (n - 1) * kTwoPi;
        const std::size_t end = cols.end_near[n] = first_failing(
            nc_, cols.end_near[n], [&](std::size_t i) { return c_at(i) + shift <= c + half_c; });
        const std::size_t begin = cols.begin_near[n] =
            first_failing(nc_, cols.begin_near[n],
                          [&](std::size_t i) { return !(c_at(i + 1) + shift >= c - half_c); });
        runs[n] = {begin, end};
      }
      std::sort(runs.begin(), runs.end());
      std::size_t next = 0;
      for (const auto& [begin, end] : runs) {
        for (std::size_t i = std::max(begin, next); i < end; ++i) add_col(i);
        next = std::max(next, end);
      }
    }
    Stats s;
    // The rows the cap meets: from the first whose upper line reaches lo (gamma ascends) to the
    // last whose lower line is within hi.
    cols.row_near =
        first_failing(ng_ - 1, cols.row_near, [&](std::size_t k) { return G[k + 1] < lo; });
    for (std::size_t j = cols.row_near; j + 1 < ng_ && !(G[j] > hi); ++j) {
      const bool row_lo = G[j] >= lo && static_cast<long>(j) != ex.row;
      const bool row_hi = G[j + 1] <= hi && static_cast<long>(j + 1) != ex.row;
      for (const Col& col : cols.list) {
        const CellStats& cs = cells_[col.i * (ng_ - 1) + j];
        s.add(cs.inside);
        if (row_lo) s.kink_row = std::max(s.kink_row, cs.kink_row_lo);
        if (row_hi) s.kink_row = std::max(s.kink_row, cs.kink_row_hi);
        if (col.plane_lo) s.kink_c = std::max(s.kink_c, cs.kink_c_lo);
        if (col.plane_hi) s.kink_c = std::max(s.kink_c, cs.kink_c_hi);
      }
    }
    // Beyond the table's first or last row the intensity is 0: a jump by that row's value and a
    // slope jump by the slope next to it, where the row is not a pole.
    auto edge = [&](std::size_t row) {
      s.i_min = 0.0;
      s.kink_row = std::max(s.kink_row, s.grad_max);
      for (const Col& col : cols.list) s.jump = std::max(s.jump, t_.grid().at(col.i, row));
    };
    if (lo < G.front() && G.front() > 1e-9) edge(0);
    if (hi > G.back() && G.back() < kPi - 1e-9) edge(ng_ - 1);
    return s;
  }

 private:
  // Whether a cap around C = c of C half-width half_c reaches C plane i (its meridian): within
  // half_c of c around the circle.
  bool cap_reaches_plane(double c, double half_c, std::size_t i) const {
    if (half_c >= kPi) return true;
    for (double shift : {0.0, -kTwoPi, kTwoPi})  // the nearest first
      if (std::abs(c_at(i) + shift - c) <= half_c) return true;
    return false;
  }
  double v(std::size_t i, std::size_t j) const { return t_.grid().at(i % nc_, j); }
  // Plane i's C, unwrapped past the last plane (i < 2 nc).
  double c_at(std::size_t i) const { return c_unwrapped_[i]; }
  // The bilinear table at grid-frame (c, gamma), C taken around the circle.
  double value(double c, double gamma) const {
    const auto& G = t_.grid().gamma_rad;
    const double gc = std::clamp(gamma, G.front(), G.back());
    std::size_t j = std::upper_bound(G.begin(), G.end(), gc) - G.begin();
    j = std::clamp<std::size_t>(j, 1, ng_ - 1) - 1;
    const double tg = (gc - G[j]) / (G[j + 1] - G[j]);
    if (nc_ == 1) return (1 - tg) * v(0, j) + tg * v(0, j + 1);
    double cw = std::fmod(c - c_at(0), kTwoPi);
    if (cw < 0) cw += kTwoPi;
    cw += c_at(0);
    std::size_t i = 0;
    while (i + 1 < nc_ && c_at(i + 1) <= cw) ++i;
    const double tc = std::clamp((cw - c_at(i)) / (c_at(i + 1) - c_at(i)), 0.0, 1.0);
    return (1 - tc) * ((1 - tg) * v(i, j) + tg * v(i, j + 1)) +
           tc * ((1 - tg) * v(i + 1, j) + tg * v(i + 1, j + 1));
  }
  // dI/dgamma of gamma cell j on plane i, and dI/dC of C cell i on row j.
  double slope_g(std::size_t i, std::size_t j) const {
    const auto& G = t_.grid().gamma_rad;
    return (v(i, j + 1) - v(i, j)) / (G[j + 1] - G[j]);
  }
  double slope_c(std::size_t i, std::size_t j) const {
    return (v(i + 1, j) - v(i, j)) / (c_at(i + 1) - c_at(i));
  }

  CellStats cell(std::size_t i, std::size_t j) const {
    const auto& G = t_.grid().gamma_rad;
    const std::size_t i1 = nc_ == 1 ? i : i + 1;
    const double v00 = v(i, j), v01 = v(i, j + 1), v10 = v(i1, j), v11 = v(i1, j + 1);
    const double g0 = G[j], g1 = G[j + 1], dg = g1 - g0;
    CellStats out;
    Stats& s = out.inside;
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
      // Slope jumps of dI/dC across the cell's two planes (plane i between C cells i - 1 and i;
      // linear in gamma along the plane, so largest at a row).
      for (std::size_t plane : {i, i + 1}) {
        double k = 0.0;
        for (std::size_t row : {j, j + 1})
          k = std::max(k,
                       std::abs(slope_c(plane % nc_, row) - slope_c((plane + nc_ - 1) % nc_, row)) *
                           inv_sin);
        (plane == i ? out.kink_c_lo : out.kink_c_hi) = k;
      }
      // The second derivative along a great circle (covariant, per radian^2): the twist over
      // sin gamma and the sphere's cot gamma terms; d2I/dgamma2 = d2I/dC2 = 0 (bilinear).
      const double f = std::abs(v11 - v10 - v01 + v00) / (dg * dc);
      if (!pole_cell) s.hess_max = 2.0 * (f / sin_lo + cot * c_abs) + cot * g_abs;
    } else if (!pole_cell) {
      s.hess_max = cot * g_abs;
    }
    // Slope jumps of dI/dgamma across the cell's two row lines (inside the table; linear in C
    // along the line, so largest at a plane).
    for (std::size_t plane : {i, i1}) {
      if (j > 0)
        out.kink_row_lo =
            std::max(out.kink_row_lo, std::abs(slope_g(plane, j) - slope_g(plane, j - 1)));
      if (j + 2 < ng_)
        out.kink_row_hi =
            std::max(out.kink_row_hi, std::abs(slope_g(plane, j + 1) - slope_g(plane, j)));
    }
    s.grad_max = std::hypot(g_abs, c_abs);
    s.grad_g_max = g_abs;
    s.grad_c_max = c_abs;
    // A pole cell: two of its gradients differ by at most twice the largest (the cone a bilinear
    // table makes at the pole), charged as one kink.
    if (pole_cell) s.kink_pole = 2.0 * s.grad_max;
    return out;
  }

  const photometry::TabularDistribution& t_;
  std::size_t nc_ = 0, ng_ = 0;
  std::vector<double> c_unwrapped_;  // plane i's C, unwrapped past the last plane (i < 2 nc)
  std::vector<CellStats> cells_;
  double peak_ = 0.0;
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
  bool flat;  // in the plane through its centroid normal to the luminaire's axis
};

// The C span (rad) of the footprint of half-angle delta of a direction whose footprint reaches
// `pole_distance` (rad) from a pole: 2 asin(sin delta / sin pole_distance); pi when it reaches the
// pole.
double footprint_c_span(double delta, double pole_distance) {
  if (!(pole_distance > delta)) return kPi;
  return 2.0 * std::asin(std::min(1.0, std::sin(delta) / std::sin(pole_distance)));
}

// The table's part of the error over `region`, relative to `den` (cd), at distance d (x D) with
// the footprint's half-angle delta = asin(rho / d); `c_span` (rad): footprint_c_span's, how much
// of C the footprint of a direction of the part spans.
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
                  double c_span, double cos_gamma, std::size_t planes, double den) {
  if (!region.any) return region.jump / den;  // beyond the table: 0, up to the edge's jump
  const double s1 = o.rms / std::max(d_over_D - o.rho, 1e-9);
  const double rows = std::floor(delta / region.dg_min) + 1.0;
  const double cs =
      planes > 1 ? std::min(static_cast<double>(planes), std::floor(c_span / region.dc_min) + 1.0)
                 : 0.0;
  // Across a row line the footprint spans the opening foreshortened by cos gamma (kForeshortened
  // in table_far_bound.h); the line's normal turns by up to 2.73 delta over the footprint
  // (away from the poles), 3 delta^2 more of the mean.
  const double across_row =
      cos_gamma < 1.0 ? 0.5 * cos_gamma * s1 + 5.0 * delta * delta : 0.5 * s1 + 2.0 * delta * delta;
  const double kinks = rows * region.kink_row * across_row +
                       (cs * region.kink_c + region.kink_pole) * (0.5 * s1 + 2.0 * delta * delta);
  const double remainder =
      (1.0 + 25.0 * delta) *
      std::min(2.0 * region.grad_max * s1,
               kinks + 0.5 * (region.hess_max + region.grad_max * delta) * s1 * s1);
  const double first_order =
      (1.0 + 25.0 * delta) * s1 * s1 *
      (kChordKappa * region.grad_max +
       kWeightKappa * (cos_gamma * region.grad_g_max + region.grad_c_max) +
       (cos_gamma < 1.0
            ? kThirdOrderKappa * o.rho / std::max(d_over_D - o.rho, 1e-9) * region.grad_g_max
            : 0.0));
  return (remainder + first_order + region.jump) / den;
}

// The ladder's rungs (x D) and the footprint's half-angle delta = asin(rho / d) at each, made
// once per emitter (the same doubles at every look-up).
struct Ladder {
  std::array<double, kTableLadderRungs> d_over_D{}, delta{};
  explicit Ladder(double rho) {
    for (int k = 0; k < kTableLadderRungs; ++k) {
      d_over_D[k] = kLadderStart * std::pow(kTableLadderRatio, k);
      delta[k] = std::asin(std::min(1.0, rho / d_over_D[k]));
    }
  }
};

// The part of a map cell from (g0, c0) (in samples) spanning 1 / kSubcells of it each way, as
// every rung sees it: its centre in the table's grid frame, the radius its directions lie
// within, and what its error is relative to (its dimmest value, or the floor).
struct Subcell {
  photometry::PhotometricAngles a;
  double sin_gamma = 0.0;  // of a.gamma
  double rc = 0.0;
  double den = 0.0;
};

Subcell subcell_of(const CellTable& cells, const glm::dmat3& to_grid, bool framed, double g0,
                   double c0, double floor_cd, CellTable::Cols& cols) {
  constexpr double step = 1.0 / kSubcells;
  // Its directions lie within rc of its centre (corners and edge midpoints; the C edges are
  // small circles, bulging a hair beyond their chord: the margin).
  const Vec3 centre = photometry::direction_of((c0 + 0.5 * step) * kMapCStepRad,
                                               (g0 + 0.5 * step) * kMapGammaStepRad);
  Subcell p;
  for (double fg : {0.0, 0.5, 1.0})
    for (double fc : {0.0, 0.5, 1.0})
      p.rc = std::max(p.rc, angle_between(centre, photometry::direction_of(
                                                      (c0 + fc * step) * kMapCStepRad,
                                                      (g0 + fg * step) * kMapGammaStepRad)));
  p.rc += 0.1 * kDegToRad;
  p.a = photometry::angles_of(to_grid * centre);
  p.sin_gamma = std::sin(p.a.gamma);
  // The dimmest value its directions see: where the table's grid is the map's, exactly over the
  // part's rectangle of angles; else over every table cell its cap reaches.
  double i_min = 0.0;
  if (framed) {
    const Stats here = cells.over_cap(p.a.c, p.a.gamma, p.rc,
                                      CellTable::cap_half_c(p.a.gamma, p.sin_gamma, p.rc), cols);
    i_min = std::isfinite(here.i_min) ? here.i_min : 0.0;
  } else {
    i_min = cells.min_over_rect(c0 * kMapCStepRad, (c0 + step) * kMapCStepRad,
                                g0 * kMapGammaStepRad, (g0 + step) * kMapGammaStepRad);
  }
  p.den = std::max(i_min, floor_cd);
  return p;
}

// One rung of one subcell's search, what no table line left out changes: the cap's radius and C
// half-width, the footprint's C span and foreshortening; and whether the search with every line
// passed there. Kept per thread for the map cell `cell` (worked out once, read by the searches
// with a line left out).
struct RungCap {
  int cell = -1;
  double radius = 0.0, half_c = 0.0, c_span = 0.0, cos_gamma = 1.0;
  signed char pass = -1;  // with every line: -1 not tried, 0 fails, 1 passes
};

// What subcell `p` of map cell `cell` needs (x D): the first rung of the ladder from which
// table_part is within `b` for every direction in it, with the table line `ex` left out.
// `rungs`: the subcell's, one per rung; the search with no line left out must come first.
float subcell_need(const CellTable& cells, bool framed, const Subcell& p, const Ladder& ladder,
                   const OpeningSize& o, double b, Excluded ex, int cell, RungCap* rungs,
                   CellTable::Cols& cols) {
  const photometry::PhotometricAngles& a = p.a;
  const bool excluding = ex.row >= 0 || ex.plane >= 0;
  auto passes = [&](int k) {
    const double d_over_D = ladder.d_over_D[k];
    const double delta = ladder.delta[k];
    RungCap& r = rungs[k];
    if (r.cell != cell) {
      r.cell = cell;
      r.pass = -1;
      r.radius = p.rc + delta;
      r.half_c = CellTable::cap_half_c(a.gamma, p.sin_gamma, r.radius);
      const double pole_distance = std::min(a.gamma - r.radius, kPi - a.gamma - r.radius) + delta;
      r.c_span = footprint_c_span(delta, pole_distance);
      // The largest |cos gamma| over the region (at an end of its gamma range), where the table's
      // gamma is the angle from the flat opening's normal and the region keeps away from the
      // poles.
      r.cos_gamma = 1.0;
      if (!framed && o.flat && pole_distance - delta >= kForeshortenedPoleDistance)
        r.cos_gamma = std::max(std::abs(std::cos(a.gamma - r.radius)),
                               std::abs(std::cos(a.gamma + r.radius)));
    }
    if (excluding && r.pass >= 0) {
      // Leaving a line out only lowers the slope jumps charged, and table_part rises with them
      // step by step (sums and products of non-negative numbers, a minimum): a rung that passes
      // with the line passes without it. Where the cap does not reach the line, leaving it out
      // changes nothing. The same answers as over_cap's, without it.
      if (r.pass == 1) return true;
      if (!cells.cap_reaches_line(a.c, a.gamma, r.radius, r.half_c, ex)) return false;
    }
    const Stats region = cells.over_cap(a.c, a.gamma, r.radius, r.half_c, cols, ex);
    const bool pass =
        table_part(region, o, d_over_D, delta, r.c_span, r.cos_gamma, cells.planes(), p.den) <= b;
    if (!excluding) r.pass = pass ? 1 : 0;
    return pass;
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
  return static_cast<float>(ladder.d_over_D[hi]);
}

// The table line a map line lies on (-1: none): map row g on a row of the table, map column c
// on a C plane. Only where the table's grid is the luminaire's (no frame), so that the map's
// interpolation fractions measure the angle from the line.
long table_row_on(const CellTable& cells, int g) {
  for (std::size_t j = 1; j + 1 < cells.rows(); ++j)  // the poles are points, not lines
    if (std::abs(cells.row_rad(j) - g * kMapGammaStepRad) < 1e-9) return static_cast<long>(j);
  return -1;
}
long table_plane_on(const CellTable& cells, int c) {
  if (cells.planes() < 2) return -1;
  const double c_rad = (c % kCSamples) * kMapCStepRad;
  for (std::size_t i = 0; i < cells.planes(); ++i)
    if (std::abs(std::remainder(cells.plane_rad(i) - c_rad, kTwoPi)) < 1e-9)
      return static_cast<long>(i);
  return -1;
}

// What a map cell allows at its four corners (1 / d, x 1/D; corner k = 2 dg + dc of (g + dg,
// c + dc)): the map interpolates 1 / d bilinearly inside the cell, so a bound on every corner
// that keeps the interpolant at or below what each direction of the cell allows.
using CornerAllow = std::array<double, 4>;

}  // namespace

std::vector<float> table_far_bound_over_D(const Emitter& e, double budget,
                                          const std::vector<float>& wanted) {
  const photometry::TabularDistribution* table = bilinear_table(e);
  if (!table || e.is_point() || !(e.largest_dimension_m > 0.0)) return {};
  const CellTable cells(*table);
  OpeningSize o{0.0, 0.0, true};
  double second_moment = 0.0;  // integral of |x - c|^2 dA over the fan from the centroid (m^4)
  for (std::size_t k = 0; k < e.vertices.size(); ++k) {
    const Vec3 p = e.vertices[k] - e.centroid;
    const Vec3 q = e.vertices[(k + 1) % e.vertices.size()] - e.centroid;
    const double area = 0.5 * glm::length(glm::cross(p, q));
    second_moment += area / 6.0 * (glm::dot(p, p) + glm::dot(q, q) + glm::dot(p, q));
    o.rho = std::max(o.rho, glm::length(p));
  }
  for (const Vec3& v : e.vertices)
    if (std::abs((e.world_to_local * (v - e.centroid)).z) > 1e-9 * e.largest_dimension_m)
      o.flat = false;
  o.rho /= e.largest_dimension_m;
  o.rms = std::sqrt(second_moment / e.area_m2) / e.largest_dimension_m;
  const bool framed = table->has_frame();
  const glm::dmat3 to_grid = framed ? table->table_from_luminaire() : glm::dmat3(1.0);
  const double floor_cd = kDimFloor * cells.peak();
  // Relative to the near value: |far - near| <= b far is within b / (1 - b) of near.
  const double b = budget / (1.0 + budget);
  // The map's lines that are table lines.
  std::vector<long> row_on(kGammaSamples, -1), plane_on(kCSamples, -1);
  if (!framed) {
    for (int g = 0; g < kGammaSamples; ++g) row_on[g] = table_row_on(cells, g);
    for (int c = 0; c < kCSamples; ++c) plane_on[c] = table_plane_on(cells, c);
  }

  const Ladder ladder(o.rho);
  const int ncell = (kGammaSamples - 1) * kCSamples;
  std::vector<CornerAllow> allow(ncell, CornerAllow{});
  std::vector<char> done(ncell, 0);
  auto sample_wanted = [&](int g, int c) { return wanted[g * kCSamples + c % kCSamples] > 0.0f; };
  auto inverse = [](float need) { return need >= kNearEverywhere ? 0.0 : 1.0 / need; };
  std::vector<int> todo;  // the cells a wanted sample is a corner of
  for (int g = 0; g + 1 < kGammaSamples; ++g)
    for (int c = 0; c < kCSamples; ++c)
      if (sample_wanted(g, c) || sample_wanted(g, c + 1) || sample_wanted(g + 1, c) ||
          sample_wanted(g + 1, c + 1))
        todo.push_back(g * kCSamples + c);
  // The cells in parallel: each reads only the table and writes only its own corners, so the
  // map is the same whatever the order (tests/nearfield/table_far_bound_parallel_test.cpp).
  // Each thread's scratch: the C cells of a cap, and the rungs of the cell it works on.
  struct Scratch {
    CellTable::Cols cols;
    std::vector<RungCap> rungs = std::vector<RungCap>(kSubcells * kSubcells * kTableLadderRungs);
  };
  tbb::enumerable_thread_specific<Scratch> scratches;
  run_in_list_order(todo.size(), [&](std::size_t n) {
    const int g = todo[n] / kCSamples, c = todo[n] % kCSamples;
    Scratch& scratch = scratches.local();
    CellTable::Cols& cols = scratch.cols;
    // The cell in kSubcells x kSubcells parts, each with its own dimmest value and its own
    // neighbourhood of the table: the cell's need is the largest of theirs.
    std::array<Subcell, kSubcells * kSubcells> parts;
    for (int sg = 0; sg < kSubcells; ++sg)
      for (int sc = 0; sc < kSubcells; ++sc)
        parts[sg * kSubcells + sc] =
            subcell_of(cells, to_grid, framed, g + static_cast<double>(sg) / kSubcells,
                       c + static_cast<double>(sc) / kSubcells, floor_cd, cols);
    auto cell_need = [&](Excluded ex) {
      float need = 0.0f;
      for (std::size_t q = 0; q < parts.size(); ++q)
        need = std::max(need, subcell_need(cells, framed, parts[q], ladder, o, b, ex, todo[n],
                                           scratch.rungs.data() + q * kTableLadderRungs, cols));
      return need;
    };
    const double all = inverse(cell_need({}));
    CornerAllow best{all, all, all, all};
    // A table line L along a side of the cell: where the footprint does not reach L (its
    // angle t from L above delta = asin(rho / d), i.e. 1 / d below sin t / rho), L's kink adds
    // nothing, so a direction allows max(all, min(without_L, sin t / rho)). The interpolant
    // keeps below that when the corners on L take all / 2, the others all / 2 plus q with
    // q t_frac <= sin t / (2 rho) (t = t_frac x the cell's width across L, sin t >= t_frac x
    // its sine), and every corner without_L: then it is at most min(without_L, all / 2 +
    // sin t / (2 rho)) <= max(all, min(without_L, sin t / rho)). Taken where that allows more
    // over the four corners than `all` alone.
    auto try_line = [&](Excluded ex, std::array<bool, 4> on_line, double q) {
      const double without = inverse(cell_need(ex));
      if (!(without > all)) return;
      CornerAllow option;
      for (int k = 0; k < 4; ++k) option[k] = std::min(without, 0.5 * all + (on_line[k] ? 0.0 : q));
      double sum_option = 0.0, sum_best = 0.0;
      for (int k = 0; k < 4; ++k) {
        sum_option += option[k];
        sum_best += best[k];
      }
      if (sum_option > sum_best) best = option;
    };
    if (all < 1.0 / kLadderStart) {
      const double across_g = std::sin(kMapGammaStepRad) / (2.0 * o.rho);
      const double sin_rows =
          std::min(std::sin(g * kMapGammaStepRad), std::sin((g + 1) * kMapGammaStepRad));
      const double across_c = sin_rows * std::sin(kMapCStepRad) / (2.0 * o.rho);
      if (row_on[g] >= 0) try_line({row_on[g], -1}, {true, true, false, false}, across_g);
      if (row_on[g + 1] >= 0) try_line({row_on[g + 1], -1}, {false, false, true, true}, across_g);
      if (plane_on[c] >= 0) try_line({-1, plane_on[c]}, {true, false, true, false}, across_c);
      const int c1 = (c + 1) % kCSamples;
      if (plane_on[c1] >= 0) try_line({-1, plane_on[c1]}, {false, true, false, true}, across_c);
    }
    allow[g * kCSamples + c] = best;
    done[g * kCSamples + c] = 1;
  });
  // A sample carries the least its (up to four) cells allow at it, so that the map's
  // interpolation (in 1 / d, between a cell's corners) never allows more inside a cell.
  std::vector<float> out(kGammaSamples * kCSamples, 0.0f);
  for (int g = 0; g < kGammaSamples; ++g)
    for (int c = 0; c < kCSamples; ++c) {
      if (!(wanted[g * kCSamples + c] > 0.0f)) continue;
      double v = kInf;
      for (int dg : {0, 1})
        for (int dc : {0, 1}) {
          const int cg = g - 1 + dg, cc = (c - 1 + dc + kCSamples) % kCSamples;
          if (cg < 0 || cg + 1 >= kGammaSamples || !done[cg * kCSamples + cc]) continue;
          // This sample is corner (1 - dg, 1 - dc) of that cell.
          v = std::min(v, allow[cg * kCSamples + cc][2 * (1 - dg) + (1 - dc)]);
        }
      out[g * kCSamples + c] =
          v > 1.0 / kNearEverywhere ? static_cast<float>(1.0 / v) : kNearEverywhere;
    }
  return out;
}

}  // namespace luxgrid::nearfield
