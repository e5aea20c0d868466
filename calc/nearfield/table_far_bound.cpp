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

// What the bound reads of the bilinear table over a set of its cells: the ranges of the two
// gradient components in each direction's own frame (d/dgamma, and d/dC per radian of arc, that
// is divided by sin gamma), the largest gradient, the dimmest value and the largest jump.
struct Stats {
  double g_lo = kInf, g_hi = -kInf;  // dI / dgamma, cd / rad
  double s_lo = kInf, s_hi = -kInf;  // dI / dC / sin gamma, cd / rad
  double grad_max = 0.0;             // cd / rad
  double i_min = kInf;               // cd
  double jump = 0.0;                 // cd
  void add(const Stats& o) {
    g_lo = std::min(g_lo, o.g_lo);
    g_hi = std::max(g_hi, o.g_hi);
    s_lo = std::min(s_lo, o.s_lo);
    s_hi = std::max(s_hi, o.s_hi);
    grad_max = std::max(grad_max, o.grad_max);
    i_min = std::min(i_min, o.i_min);
    jump = std::max(jump, o.jump);
  }
};

// The range of a / s for a in [a_lo, a_hi] and s in [s_lo, s_hi], s_lo > 0.
void quotient_range(double a_lo, double a_hi, double s_lo, double s_hi, double& lo, double& hi) {
  const double q[] = {a_lo / s_lo, a_lo / s_hi, a_hi / s_lo, a_hi / s_hi};
  lo = *std::min_element(q, q + 4);
  hi = *std::max_element(q, q + 4);
}

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
      const auto& C = t_.grid().c_rad;
      for (std::size_t i = 0; i < nc_; ++i) {
        const double c0 = C[i], c1 = i + 1 < nc_ ? C[i + 1] : C[0] + kTwoPi;
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
    // Beyond the table's first or last row the intensity is 0: a jump by that row's value where
    // the row is not a pole.
    auto edge = [&](std::size_t row) {
      s.i_min = 0.0;
      s.g_lo = std::min(s.g_lo, 0.0);
      s.g_hi = std::max(s.g_hi, 0.0);
      s.s_lo = std::min(s.s_lo, 0.0);
      s.s_hi = std::max(s.s_hi, 0.0);
      for (std::size_t i : cols) s.jump = std::max(s.jump, t_.grid().at(i, row));
    };
    if (lo < G.front() && G.front() > 1e-9) edge(0);
    if (hi > G.back() && G.back() < kPi - 1e-9) edge(ng_ - 1);
    return s;
  }

 private:
  Stats cell(std::size_t i, std::size_t j) const {
    const auto& g = t_.grid();
    const std::size_t i1 = nc_ == 1 ? i : (i + 1 < nc_ ? i + 1 : 0);
    const double v00 = g.at(i, j), v01 = g.at(i, j + 1), v10 = g.at(i1, j), v11 = g.at(i1, j + 1);
    const double g0 = g.gamma_rad[j], g1 = g.gamma_rad[j + 1], dg = g1 - g0;
    Stats s;
    s.i_min = std::min({v00, v01, v10, v11});
    // Bilinear in (C, gamma): dI/dgamma is linear in C across the cell, dI/dC linear in gamma.
    s.g_lo = std::min(v01 - v00, v11 - v10) / dg;
    s.g_hi = std::max(v01 - v00, v11 - v10) / dg;
    s.s_lo = s.s_hi = 0.0;
    if (nc_ > 1) {
      const double c0 = g.c_rad[i], c1 = i + 1 < nc_ ? g.c_rad[i + 1] : g.c_rad[0] + kTwoPi;
      double a0 = (v10 - v00) / (c1 - c0), a1 = (v11 - v01) / (c1 - c0);
      const double sin0 = std::sin(g0), sin1 = std::sin(g1);
      const double sin_hi = g0 <= 0.5 * kPi && g1 >= 0.5 * kPi ? 1.0 : std::max(sin0, sin1);
      const double sin_lo = std::min(sin0, sin1);
      if (sin_lo > 1e-9) {
        quotient_range(std::min(a0, a1), std::max(a0, a1), sin_lo, sin_hi, s.s_lo, s.s_hi);
      } else {
        // A pole row: its C differences are a jump at the pole (none where the row is averaged,
        // tabular_distribution.h); the other row's grow from 0 at the pole as t, over
        // sin(t dgamma), t / sin(t dgamma) in [1 / dgamma, 1 / sin dgamma].
        const bool at_start = sin0 <= 1e-9;
        double& pole_a = at_start ? a0 : a1;
        s.jump = std::abs(at_start ? v10 - v00 : v11 - v01);
        pole_a = 0.0;
        const double other = at_start ? a1 : a0;
        const double p_lo = 1.0 / dg,
                     p_hi = 1.0 / std::max(std::sin(std::min(dg, kPi - 1e-3)), 1e-3);
        quotient_range(std::min(other, 0.0), std::max(other, 0.0), 1.0 / p_hi, 1.0 / p_lo, s.s_lo,
                       s.s_hi);
      }
    }
    s.grad_max = std::hypot(std::max(std::abs(s.g_lo), std::abs(s.g_hi)),
                            std::max(std::abs(s.s_lo), std::abs(s.s_hi)));
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

// The table's part of the error at half-angle delta over `region`, relative to `den` (cd).
double table_part(const Stats& region, double radius_of_rotation, double delta, double den) {
  if (!(region.g_hi >= region.g_lo)) return 0.0;  // no cell: the intensity is 0 there
  // Two gradients of the region differ by at most the spread of their components plus the turn
  // of the frame (e_gamma, e_C) between their directions, |e(a) - e(b)| <= 2.
  const double osc = (region.g_hi - region.g_lo) + (region.s_hi - region.s_lo) +
                     region.grad_max * std::min(4.0, radius_of_rotation);
  return (osc * delta + region.grad_max * kFirstOrderKappa * delta * delta + region.jump) / den;
}

}  // namespace

std::vector<float> table_far_bound_over_D(const Emitter& e, double budget,
                                          const std::vector<float>& wanted) {
  const photometry::TabularDistribution* table = bilinear_table(e);
  if (!table || e.is_point() || !(e.largest_dimension_m > 0.0)) return {};
  const CellTable cells(*table);
  double rho = 0.0;  // circumradius about the centroid (m)
  for (const Vec3& v : e.vertices) rho = std::max(rho, glm::length(v - e.centroid));
  const double rho_over_D = rho / e.largest_dimension_m;
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
      // The cell's directions lie within rc of its centre (corners and edge midpoints; the C
      // edges are small circles, bulging less than a degree beyond their chord at 7.5 degrees).
      const Vec3 centre =
          photometry::direction_of((c + 0.5) * kMapCStepRad, (g + 0.5) * kMapGammaStepRad);
      double rc = 0.0;
      for (double fg : {0.0, 0.5, 1.0})
        for (double fc : {0.0, 0.5, 1.0})
          rc = std::max(
              rc, angle_between(centre, photometry::direction_of((c + fc) * kMapCStepRad,
                                                                 (g + fg) * kMapGammaStepRad)));
      rc += 0.25 * kDegToRad;
      const photometry::PhotometricAngles a = photometry::angles_of(to_grid * centre);
      const Stats here = cells.over_cap(a.c, a.gamma, rc);
      const double den = std::max(std::isfinite(here.i_min) ? here.i_min : 0.0, floor_cd);
      auto passes = [&](int k) {
        const double d_over_D = kLadderStart * std::pow(kTableLadderRatio, k);
        const double delta = std::asin(std::min(1.0, rho_over_D / d_over_D));
        const double radius = rc + delta;
        const Stats region = cells.over_cap(a.c, a.gamma, radius);
        const double half_c = a.gamma - radius <= 0.0 || a.gamma + radius >= kPi
                                  ? kPi
                                  : std::asin(std::min(1.0, std::sin(radius) / std::sin(a.gamma)));
        return table_part(region, 2.0 * radius + 4.0 * half_c, delta, den) <= b;
      };
      float need = kNearEverywhere;
      if (passes(kTableLadderRungs - 1)) {
        int lo = -1, hi = kTableLadderRungs - 1;  // lo fails (or none), hi passes
        if (passes(0))
          hi = 0;
        else
          lo = 0;
        while (hi - lo > 1) {
          const int mid = (lo + hi) / 2;
          (passes(mid) ? hi : lo) = mid;
        }
        need = static_cast<float>(kLadderStart * std::pow(kTableLadderRatio, hi));
      }
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
