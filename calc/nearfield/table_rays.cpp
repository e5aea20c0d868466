#include "calc/nearfield/table_rays.h"

#include <array>
#include <cmath>

#include "calc/nearfield/gauss_legendre.h"

namespace luxgrid::nearfield {
namespace {

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

// One ray's ends: through its known edges (ends_through_edges), or by trying every edge.
inline void one_ray_ends(const Polygon2& poly, bool inside, double inv_sigma, const RayJob& job,
                         RayEnds& end) {
  const double cp = job.c, sp = job.s;
  end.ok = false;
  if (job.near_edge >= 0) {
    const int near = job.near_edge, far = job.far_edge;
    const EdgeEnds<double> e =
        ends_through_edges(cp, sp, poly.edge[near].x, poly.edge[near].y, poly.cross[near],
                           poly.edge[far].x, poly.edge[far].y, poly.cross[far], inv_sigma);
    if (!e.ok) return;
    end = {true,       e.sin_near, e.cos_near, e.sin_far, e.cos_far,
           e.tan_near, e.tan_far,  e.g_near,   e.g_far};
    return;
  }
  double rho_min, rho_max;
  if (!ray_interval(poly, cp, sp, inside, rho_min, rho_max)) return;
  const double t_near = rho_min * inv_sigma, t_far = rho_max * inv_sigma;
  const double cos_near = 1.0 / std::sqrt(1.0 + t_near * t_near);
  const double cos_far = 1.0 / std::sqrt(1.0 + t_far * t_far);
  const double sin_near = t_near * cos_near, sin_far = t_far * cos_far;
  end = {true,
         sin_near,
         cos_near,
         sin_far,
         cos_far,
         t_near,
         t_far,
         quadrant_angle(sin_near, cos_near),
         quadrant_angle(sin_far, cos_far)};
}

// ends_through_edges over the lanes of four rays.
LUXGRID_LANE void ends_by_edges4_kernel(const Polygon2& poly, const RayJob* jobs, double inv_sigma,
                                        RayEnds* ends) {
  using simd::D4;
  const EdgeEnds<D4> e = ends_through_edges(
      simd::make<D4>([&](int l) { return jobs[l].c; }),
      simd::make<D4>([&](int l) { return jobs[l].s; }),
      simd::make<D4>([&](int l) { return poly.edge[jobs[l].near_edge].x; }),
      simd::make<D4>([&](int l) { return poly.edge[jobs[l].near_edge].y; }),
      simd::make<D4>([&](int l) { return poly.cross[jobs[l].near_edge]; }),
      simd::make<D4>([&](int l) { return poly.edge[jobs[l].far_edge].x; }),
      simd::make<D4>([&](int l) { return poly.edge[jobs[l].far_edge].y; }),
      simd::make<D4>([&](int l) { return poly.cross[jobs[l].far_edge]; }), inv_sigma);
  for (int l = 0; l < simd::kLanes; ++l) {
    if (!e.ok[l]) {
      ends[l].ok = false;
      continue;
    }
    ends[l] = {true,          e.sin_near[l], e.cos_near[l], e.sin_far[l], e.cos_far[l],
               e.tan_near[l], e.tan_far[l],  e.g_near[l],   e.g_far[l]};
  }
}

}  // namespace

LUXGRID_MULTIVERSION(void, ends_by_edges4,
                     (const Polygon2& poly, const RayJob* jobs, double inv_sigma, RayEnds* ends),
                     (poly, jobs, inv_sigma, ends), ends_by_edges4_kernel)

void ray_ends(const Polygon2& poly, bool inside, double inv_sigma, const RayJob* jobs,
              std::size_t count, RayEnds* ends) {
  std::size_t r = 0;
  while (r + 4 <= count) {
    if (jobs[r].near_edge >= 0 && jobs[r + 1].near_edge >= 0 && jobs[r + 2].near_edge >= 0 &&
        jobs[r + 3].near_edge >= 0) {
      ends_by_edges4(poly, jobs + r, inv_sigma, ends + r);
      r += 4;
    } else {
      one_ray_ends(poly, inside, inv_sigma, jobs[r], ends[r]);
      ++r;
    }
  }
  for (; r < count; ++r) one_ray_ends(poly, inside, inv_sigma, jobs[r], ends[r]);
}

std::size_t cell_rays(const Polygon2& poly, const PsiCells& psi,
                      const photometry::TabularDistribution& table, std::vector<RayJob>& jobs_out) {
  const std::vector<Break>& psi_breaks = psi.breaks;
  const std::size_t cell_count = psi_breaks.size() - 1;
  std::size_t ray_count = 0;
  for (std::size_t k = 0; k < cell_count; ++k) ray_count += psi_breaks[k].points;
  if (jobs_out.size() < ray_count) jobs_out.resize(ray_count);
  RayJob* const jobs = jobs_out.data();
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
  return job_count;
}

}  // namespace luxgrid::nearfield
