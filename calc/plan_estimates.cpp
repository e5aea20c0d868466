#include "calc/plan_estimates.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "calc/nearfield/far_field_bound.h"

namespace luxgrid::calc {
namespace {

// The promise covers points brighter than this fraction of their surface's maximum
// (docs/accuracy.md): dimmer ones are held to the absolute error this fraction of the maximum
// allows, as report/diff.h's kRelativeFloor measures them.
constexpr double kPromiseFloor = 0.01;

}  // namespace

double promised_error(Quality q) {
  switch (q) {
    case Quality::standard: return nearfield::kStandardPromise;
    case Quality::high: return nearfield::kHighPromise;
    case Quality::draft:
    case Quality::reference: return 0.0;
  }
  return 0.0;
}

double refinement_target(Quality q) {
  return q == Quality::reference ? kReferenceConvergenceTarget : promised_error(q);
}

std::vector<size_t> probe_points(const geometry::SurfaceGrid& grid) {
  std::vector<size_t> active;
  for (size_t i = 0; i < grid.points.size(); ++i)
    if (grid.active.empty() || grid.active[i]) active.push_back(i);
  if (active.size() <= kProbePointsPerSurface) return active;
  std::vector<size_t> picked;
  // Centres of kProbePointsPerSurface equal runs of the index order: spread over the rows.
  for (size_t k = 0; k < kProbePointsPerSurface; ++k)
    picked.push_back(active[(2 * k + 1) * active.size() / (2 * kProbePointsPerSurface)]);
  return picked;
}

void add_shadow_probes(const geometry::SurfaceGrid& grid, const std::vector<double>& E_direct,
                       std::vector<size_t>& picked) {
  std::vector<char> taken(grid.points.size(), 0);
  for (size_t i : picked) taken[i] = 1;
  std::vector<size_t> rest;
  for (size_t i = 0; i < grid.points.size(); ++i)
    if ((grid.active.empty() || grid.active[i]) && !taken[i]) rest.push_back(i);
  const size_t n = std::min(kShadowProbesPerSurface, rest.size());
  std::partial_sort(rest.begin(), rest.begin() + static_cast<std::ptrdiff_t>(n), rest.end(),
                    [&](size_t a, size_t b) {
                      return E_direct[a] < E_direct[b] || (E_direct[a] == E_direct[b] && a < b);
                    });
  picked.insert(picked.end(), rest.begin(), rest.begin() + static_cast<std::ptrdiff_t>(n));
}

geometry::SurfaceGrid probe_grid(const geometry::SurfaceGrid& grid,
                                 const std::vector<size_t>& picked) {
  geometry::SurfaceGrid g;
  g.name = grid.name;
  g.kind = geometry::SurfaceGrid::Kind::points;
  g.nu = static_cast<int>(picked.size());
  g.nv = 1;
  g.quantity = grid.quantity;
  for (size_t i : picked) {
    g.points.push_back(grid.points[i]);
    g.normals.push_back(grid.normals[i]);
  }
  g.active.assign(picked.size(), true);
  return g;
}

double patch_size_estimate(const geometry::SurfaceGrid& grid, const std::vector<double>& E,
                           const std::vector<double>& E_indirect,
                           const std::vector<size_t>& probe_index,
                           const std::vector<double>& coarse_lx, size_t* counted) {
  const auto active = [&](size_t i) { return grid.active.empty() || grid.active[i]; };
  double e_max = 0.0;
  for (size_t i = 0; i < E.size(); ++i)
    if (active(i)) e_max = std::max(e_max, E[i]);
  const double floor_lx = kPromiseFloor * e_max;
  double worst = 0.0;
  size_t count = 0;
  for (size_t k = 0; k < probe_index.size(); ++k) {
    const size_t i = probe_index[k];
    if (!active(i) || !(std::max(E[i], floor_lx) > 0.0)) continue;
    ++count;
    worst = std::max(worst, std::abs(E_indirect[i] - coarse_lx[k]) / std::max(E[i], floor_lx));
  }
  if (counted) *counted = count;
  return worst;
}

double coarse_level_difference(const geometry::SurfaceGrid& grid, const std::vector<double>& E,
                               const std::vector<size_t>& probe_index,
                               const std::vector<double>& coarse_lx,
                               const std::vector<double>& coarser_lx) {
  // patch_size_estimate's sum with the 2h level in E_ind(h)'s place: the same probes, the same
  // denominators (E at h), so that d2 / d1 compares the differences alone.
  std::vector<double> coarse_on_grid(E.size(), 0.0);
  for (size_t k = 0; k < probe_index.size(); ++k) coarse_on_grid[probe_index[k]] = coarse_lx[k];
  return patch_size_estimate(grid, E, coarse_on_grid, probe_index, coarser_lx);
}

PatchErrorEstimate richardson_patch_error(double d_fine, double d_coarse) {
  if (d_coarse < 0.0) return {d_fine, 1.0};  // no 4h level: first order assumed
  // d2 / d1 = 2^p where E(h) = E(0) + c h^p; d1 = 0 (the two finer meshes agree at every probe)
  // has nothing to extrapolate. Ratios outside the range (d2 <= d1 and d2 = 0 included) take the
  // range's ends.
  double order = kMinPatchOrder;
  if (d_fine > 0.0 && d_coarse > d_fine)
    order = std::clamp(std::log2(d_coarse / d_fine), kMinPatchOrder, kMaxPatchOrder);
  return {d_fine / (std::exp2(order) - 1.0), order};
}

PatchErrorEstimate local_patch_error(
    const geometry::SurfaceGrid& grid, const std::vector<double>& E,
    const std::vector<double>& E_indirect, const std::vector<size_t>& probe_index,
    const std::vector<char>& local_probe, const std::vector<double>& level_h_lx,
    const std::vector<double>& level_2h_lx, const std::vector<double>& level_4h_lx) {
  struct Group {
    std::vector<size_t> index;
    std::vector<double> h, h2, h4;
  } cut, kept;
  for (size_t k = 0; k < probe_index.size(); ++k) {
    Group& g = local_probe[k] ? cut : kept;
    g.index.push_back(probe_index[k]);
    g.h.push_back(level_h_lx[k]);
    g.h2.push_back(level_2h_lx[k]);
    g.h4.push_back(level_4h_lx[k]);
  }
  const double first_order = patch_size_estimate(grid, E, E_indirect, cut.index, cut.h);
  // The others: the order over them alone, each probe's E_ind(0) extrapolated with it from its h
  // and 2h values, and the run's distance from that.
  const PatchErrorEstimate order =
      richardson_patch_error(coarse_level_difference(grid, E, kept.index, kept.h, kept.h2),
                             coarse_level_difference(grid, E, kept.index, kept.h2, kept.h4));
  std::vector<double> extrapolated(kept.index.size());
  for (size_t k = 0; k < kept.index.size(); ++k)
    extrapolated[k] = kept.h[k] - (kept.h2[k] - kept.h[k]) / (std::exp2(order.order) - 1.0);
  const double others = patch_size_estimate(grid, E, E_indirect, kept.index, extrapolated);
  if (first_order > others) return {first_order, kMinPatchOrder};
  return {others, order.order};
}

std::vector<char> local_refinement_probes(const std::vector<double>& E_direct,
                                          const std::vector<size_t>& probe_index,
                                          const std::vector<double>& probe_lx,
                                          const std::vector<double>& coarse_lx, double threshold) {
  double known_max = 0.0;
  for (double e : E_direct) known_max = std::max(known_max, e);
  for (size_t k = 0; k < probe_index.size(); ++k)
    known_max = std::max(known_max, E_direct[probe_index[k]] + probe_lx[k]);
  const double floor_lx = kPromiseFloor * known_max;
  std::vector<char> centre(probe_index.size(), 0);
  for (size_t k = 0; k < probe_index.size(); ++k) {
    const double E = std::max(E_direct[probe_index[k]] + probe_lx[k], floor_lx);
    if (E > 0.0 && std::abs(probe_lx[k] - coarse_lx[k]) > threshold * E) centre[k] = 1;
  }
  return centre;
}

ProbeFigure patch_size_estimate_at_probes(const geometry::SurfaceGrid& grid,
                                          const std::vector<double>& E_direct,
                                          const std::vector<size_t>& probe_index,
                                          const std::vector<double>& E_indirect_probe,
                                          const std::vector<double>& coarse_lx,
                                          double max_indirect_lx) {
  const auto active = [&](size_t i) { return grid.active.empty() || grid.active[i]; };
  double direct_max = 0.0;
  for (size_t i = 0; i < E_direct.size(); ++i)
    if (active(i)) direct_max = std::max(direct_max, E_direct[i]);
  // The surface's largest E lies between the largest known one (E_direct anywhere, the reflected
  // light adding to it; E at the probes) and the largest E_direct plus the bound; so does the
  // floor, a fixed share of it.
  double known_max = direct_max;
  for (size_t k = 0; k < probe_index.size(); ++k)
    if (active(probe_index[k]))
      known_max = std::max(known_max, E_direct[probe_index[k]] + E_indirect_probe[k]);
  const double floor_bound_lx = kPromiseFloor * (direct_max + max_indirect_lx);
  const double floor_least_lx = kPromiseFloor * known_max;
  // A probe at least as bright as the floor's bound counts by its own E, as patch_size_estimate
  // counts it; a darker one by at most its difference over max(E, the floor's least value).
  double worst = 0.0, dark_most = 0.0;
  for (size_t k = 0; k < probe_index.size(); ++k) {
    const size_t i = probe_index[k];
    if (!active(i)) continue;
    // The sum patch_size_estimate forms, in the same order.
    const double E = E_direct[i] + E_indirect_probe[k];
    const double difference = std::abs(E_indirect_probe[k] - coarse_lx[k]);
    if (E >= floor_bound_lx && E > 0.0) {
      worst = std::max(worst, difference / E);
      continue;
    }
    const double least = std::max(E, floor_least_lx);
    dark_most = least > 0.0 ? std::max(dark_most, difference / least)
                            : std::numeric_limits<double>::infinity();
  }
  // Where no dark probe can exceed the bright ones, the floor does not change the largest.
  if (dark_most <= worst) return {worst, true};
  return {dark_most, false};
}

SurfaceEstimate estimate_surface(const geometry::SurfaceGrid& grid, const std::vector<double>& E,
                                 const std::vector<double>& E_indirect,
                                 const DirectEstimateInputs& direct,
                                 const IndirectEstimateInputs& indirect, size_t s) {
  SurfaceEstimate est;
  est.surface = grid.name;
  const auto active = [&](size_t i) { return grid.active.empty() || grid.active[i]; };
  double e_max = 0.0;
  for (size_t i = 0; i < E.size(); ++i)
    if (active(i)) e_max = std::max(e_max, E[i]);
  // As `luxgrid cost` measures (report/diff.h): relative to the point, but no less than 1 % of
  // the surface's maximum, so a point in near darkness counts by its absolute error.
  const double floor_lx = kPromiseFloor * e_max;
  const auto counted = [&](size_t i) { return active(i) && std::max(E[i], floor_lx) > 0.0; };
  const auto denom = [&](size_t i) { return std::max(E[i], floor_lx); };
  est.direct = direct.estimated ? 0.0 : -1.0;
  if (direct.estimated && s < direct.error_lx.size())
    for (size_t i = 0; i < E.size(); ++i)
      if (counted(i)) est.direct = std::max(est.direct, direct.error_lx[s][i] / denom(i));
  if (!indirect.ran) return est;
  est.bounces = 0.0;
  for (size_t i = 0; i < E.size(); ++i)
    if (counted(i))
      est.bounces = std::max(est.bounces, indirect.residual * E_indirect[i] / denom(i));
  // No probes: `draft` solves one mesh, and its patch size is not estimated (-1, not 0).
  if (s < indirect.probe_index.size()) {
    est.patch_difference = patch_size_estimate(grid, E, E_indirect, indirect.probe_index[s],
                                               indirect.coarse_lx[s], &est.probe_points);
    const double d_coarse =
        s < indirect.coarser_lx.size()
            ? coarse_level_difference(grid, E, indirect.probe_index[s], indirect.coarse_lx[s],
                                      indirect.coarser_lx[s])
            : -1.0;
    const bool local = s < indirect.local_probe.size() && s < indirect.coarsest_lx.size();
    const PatchErrorEstimate p =
        local ? local_patch_error(grid, E, E_indirect, indirect.probe_index[s],
                                  indirect.local_probe[s], indirect.coarse_lx[s],
                                  indirect.coarser_lx[s], indirect.coarsest_lx[s])
              : richardson_patch_error(est.patch_difference, d_coarse);
    est.patch_size = p.error;
    est.patch_order = p.order;
  }
  return est;
}

void estimate_errors(Results& results, const DirectEstimateInputs& direct,
                     const IndirectEstimateInputs& indirect) {
  Plan& plan = results.plan;
  const double promise = promised_error(results.quality);
  plan.promise = promise;
  plan.errors_estimated = true;
  plan.estimates.clear();
  double worst_patch = 0.0, worst_bounces = 0.0;
  for (size_t s = 0; s < results.surfaces.size(); ++s) {
    const SurfaceResult& r = results.surfaces[s];
    SurfaceEstimate est = estimate_surface(r.grid, r.E, r.E_indirect, direct, indirect, s);
    if (indirect.ran) {
      worst_patch = std::max(worst_patch, est.patch_size);
      worst_bounces = std::max(worst_bounces, est.bounces);
    }
    plan.estimates.push_back(std::move(est));
  }
  if (indirect.ran && plan.indirect_run) {
    IndirectRunPlan& run = *plan.indirect_run;
    run.estimated = true;
    run.patch_size_m = indirect.patch_size_m;
    run.coarse_patch_size_m = indirect.coarse_patch_size_m;
    run.coarser_patch_size_m = indirect.coarser_patch_size_m;
    run.probe_points_per_surface = kProbePointsPerSurface + kShadowProbesPerSurface;
    run.worst_patch_size = worst_patch;
    run.worst_bounces = worst_bounces;
  }
}

}  // namespace luxgrid::calc
