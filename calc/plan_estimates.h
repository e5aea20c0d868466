#pragma once
// The plan's estimate of its own error (docs/accuracy.md, "The plan's own estimate"): what each
// quality promises, and per surface what each remaining approximation is estimated to cost,
// from measurements the run makes, not from constants:
//   - far field and fixed rule for a luminaire-point pair: the error the near/far map measured
//     at the distance it chose (nearfield/far_field_bound.h), falling as d_far / d beyond it,
//     weighted by each pair's share of the point's illuminance (nearfield::estimated_pair_error);
//   - the interreflection mesh's patch size h: Richardson extrapolation with the order measured
//     per surface [Richardson1911] [Roache1994, the observed order]. The rooms are meshed as the
//     run meshes them (each mesh cut where its own light jumps, the same rule at every size) at h,
//     2h and 4h; the coarser two are gathered at the probe points only (probe_points, evenly
//     spread, and add_shadow_probes, where the direct light is weakest).
//     Per surface, d1 = max |E(h) - E(2h)| and d2 = max |E(2h) - E(4h)| over the probes (relative
//     to the point's E as the promise counts it); where E(h) = E(0) + c h^p, d2 / d1 = 2^p, so p =
//     log2(d2 / d1) and E(h) - E(0) = d1 / (2^p - 1). The maxima, not each probe's ratio, give p: a
//     probe's differences change sign from mesh to mesh where patch edges move, the surface's
//     largest ones much less. p is clamped to [kMinPatchOrder, kMaxPatchOrder]
//     (richardson_patch_error): a clamp only ever raises the estimate above what the measured
//     order would give, except below kMinPatchOrder, where the coarse meshes are not in the
//     asymptotic range (d2 <= d1 included) and the estimate is d1, the first-order one. Without a
//     4h level (none was run) p = 1 is assumed and the estimate is d1;
//   - bounces not followed: the radiosity residual (the geometric tail's estimated error, or
//     for a fixed N the tail rho^N / (1 - rho) the solve did not follow, radiosity.h) times
//     the point's indirect share E_ind / E;
//   - textures: luxgrid has none (one reflectance per face, no texture maps), so none is
//     estimated; the plan says so.
// A surface whose total exceeds the promise gets a warning.
#include <string>
#include <vector>

#include "calc/results.h"
#include "geometry/surface_grid.h"

namespace luxgrid::calc {

// The relative error a quality promises against `reference` at every point brighter than 1 % of
// its surface's maximum; 0 when it promises no number (draft: none; reference: the yardstick).
double promised_error(Quality q);

// What `reference`, the yardstick, holds its own reflected light to: its estimate at most this at
// every point (relative, as the promises count), so that a `high` run's 0.3 % is measured against
// something several times finer.
inline constexpr double kReferenceConvergenceTarget = 0.002;

// The error the interreflection mesh is refined for (calc/pipeline.cpp): the promise at
// `standard` and `high`, kReferenceConvergenceTarget at `reference`, 0 (no refinement) at
// `draft`.
double refinement_target(Quality q);

// The share of that target the interreflection mesh's patch size is given: the run refines the
// mesh while a surface's difference d1 exceeds it (calc/pipeline.cpp); the rest is the direct
// light's and the bounces'. A refinement a limit stopped is a warning only where the plan's
// total estimate of the mesh that stayed exceeds the whole target (report/plan_text.h).
inline constexpr double kPatchShareOfPromise = 0.5;

// Probe points per surface for the patch-size estimate: the coarse runs gather at these only,
// so they cost the coarse meshes (a quarter and a sixteenth of the patches) and little more.
inline constexpr size_t kProbePointsPerSurface = 48;

// The range of orders of convergence in h the patch-size estimate extrapolates with, [1, 2], so
// that the estimate lies between d1 / 3 and d1. Below: patch-constant radiosity is first order
// in the exitance and a gathered point's E integrates that error, so a measured order below 1
// (d2 <= d1 included) says the coarse meshes are not in the asymptotic range, not that the
// error falls more slowly; the estimate then is d1, the first-order estimate the plan made before
// it measured orders, never less. (Taking such orders at their word, down to 1/2, made the
// office's activity faces 0.96 % against 0.18 % measured, docs/accuracy.md.) Above: the gather
// of a piecewise-constant exitance over a smooth kernel can cancel the first-order term (the
// midpoint rule's second order), but nothing in the method cancels the second; a measured order
// above 2 is taken for a coincidence of the coarse meshes and clamped to 2 (the estimate d1 / 3,
// larger than the measured order's).
inline constexpr double kMinPatchOrder = 1.0;
inline constexpr double kMaxPatchOrder = 2.0;

// Richardson's estimate of the error at h from the differences between three meshes:
// `d_fine` = |E(h) - E(2h)|, `d_coarse` = |E(2h) - E(4h)| (any common scale; d_coarse < 0: no
// 4h level). `order` is the order it extrapolated with: measured and clamped, or 1 assumed
// without a 4h level.
struct PatchErrorEstimate {
  double error = 0.0;
  double order = 1.0;
};
PatchErrorEstimate richardson_patch_error(double d_fine, double d_coarse);

// The patch-size estimate of a surface after a local step (IndirectEstimateInputs::local_probe):
// the levels are no longer one mesh halved, so no order can be measured where the mesh was cut.
//   - at the probes cut around: d1 = |E_ind - E_ind(h)|, the first-order estimate (the one the
//     plan makes without a measured order, kMinPatchOrder);
//   - at the others the mesh is h's as before: the order p measured over them alone (as
//     richardson_patch_error, from h, 2h and 4h), each one's E_ind(0) extrapolated with it,
//     E_ind(h) - (E_ind(2h) - E_ind(h)) / (2^p - 1), and the estimate |E_ind - E_ind(0)|: where
//     the step did not move a probe, Richardson's estimate of it, and the step's move counted
//     with its sign (towards the extrapolated value or away from it).
// The larger of the two; `order` is 1 where the first decides, else the measured one. `E`,
// `E_indirect` per point of `grid`, the levels per probe.
PatchErrorEstimate local_patch_error(
    const geometry::SurfaceGrid& grid, const std::vector<double>& E,
    const std::vector<double>& E_indirect, const std::vector<size_t>& probe_index,
    const std::vector<char>& local_probe, const std::vector<double>& level_h_lx,
    const std::vector<double>& level_2h_lx, const std::vector<double>& level_4h_lx);

// Up to kProbePointsPerSurface active points of `grid`, evenly spread over its index order
// (rows of a grid), and the grid reduced to them.
std::vector<size_t> probe_points(const geometry::SurfaceGrid& grid);

// Probes added per surface where its direct light is weakest: a point in a shadow gets its light
// by reflection, so the reflected light's error is the largest share of its E there
// (examples/lshape's workplane beside the cabinet: 1.5 % from `reference` where the evenly spread
// probes see at most 0.5 % between h and 2h). They count in the estimate, not in the patch-size
// choice (calc/pipeline.cpp), which the evenly spread probes make alone.
inline constexpr size_t kShadowProbesPerSurface = 16;

// Where the mesh at half the patch size would cost more than the refinement's work limit and the
// estimate exceeds the promise (calc/pipeline.cpp, refine_locally), the run cuts it finer only
// around the probes that ask for it: every patch within this many patch sizes of such a probe is
// cut into quarters and the rooms solved again. tests/rooms/tshape at `standard` (the cabinet
// 5 cm from wall 4, 0.25 m patches): 340 patches cut around 3 probes, the wall's worst point from
// 0.39 % to 0.18 % of the room's reference (docs/accuracy.md, "The local step"). The reach costs
// patches, not time: the step's cost is the second solve of the whole mesh.
inline constexpr double kLocalRefinementReach = 4.0;

// Per probe of one surface (probe_index, `probe_lx` the run's E_ind at h there, `coarse_lx` at
// 2h): 1 where |E_ind(h) - E_ind(2h)| exceeds `threshold` of the probe's E (E_direct plus
// E_ind(h), no less than 1 % of the largest E known: at the probes, and E_direct anywhere): the
// probes a local step cuts the mesh around.
std::vector<char> local_refinement_probes(const std::vector<double>& E_direct,
                                          const std::vector<size_t>& probe_index,
                                          const std::vector<double>& probe_lx,
                                          const std::vector<double>& coarse_lx, double threshold);

// Appends to `picked` (probe_points' choice) up to kShadowProbesPerSurface active points of
// `grid` not in it: those with the smallest `E_direct` (per point of `grid`; ties: lower index).
void add_shadow_probes(const geometry::SurfaceGrid& grid, const std::vector<double>& E_direct,
                       std::vector<size_t>& picked);
geometry::SurfaceGrid probe_grid(const geometry::SurfaceGrid& grid,
                                 const std::vector<size_t>& picked);

// What the direct calculation estimated (calc/direct.h): per surface and point, the error in lx
// (maintained); `estimated` false when the far field ran at every distance without a map.
struct DirectEstimateInputs {
  bool estimated = true;
  std::vector<std::vector<double>> error_lx;
};

// What the indirect calculation measured for the estimate.
struct IndirectEstimateInputs {
  bool ran = false;
  double residual = 0.0;  // relative to the reflected flux (largest over rooms)
  double patch_size_m = 0.0, coarse_patch_size_m = 0.0;
  std::vector<std::vector<size_t>> probe_index;  // per surface: the probe points
  // Per surface: how many of probe_index are probe_points' (the rest: add_shadow_probes').
  std::vector<size_t> spread_probes;
  std::vector<std::vector<double>> coarse_lx;  // per surface: E_ind at 2h there, maintained lx
  // At 4h: as coarse_lx, for the measured order; empty where no 4h level was run.
  double coarser_patch_size_m = 0.0;
  std::vector<std::vector<double>> coarser_lx;
  // After a local step (local_refinement_probes, calc/pipeline.cpp): per surface and probe, 1
  // where the mesh was cut finer around that probe; coarse_lx, coarser_lx and coarsest_lx then
  // hold the levels h (the mesh before the step, at the run's own patch size), 2h and 4h. Empty
  // without a local step.
  std::vector<std::vector<char>> local_probe;
  std::vector<std::vector<double>> coarsest_lx;
  // Not for the estimate: the reflected light leaving through openings (IndirectResult's), for
  // the daylight plan's balance.
  double escaped_flux_lm = 0.0;
};

// The difference between the meshes at h and 2h on one surface: the largest
// |E_ind(h) - E_ind(2h)| over its probe points, relative to the point's E (direct + indirect) but
// no less than 1 % of the surface's largest E, as the promise counts it (the patch-size choice
// of calc/pipeline.cpp and d1 of the estimate). `E` and `E_indirect` per point of `grid`,
// `coarse_lx` per probe; `counted` (if not null) gets the number of probes that count.
double patch_size_estimate(const geometry::SurfaceGrid& grid, const std::vector<double>& E,
                           const std::vector<double>& E_indirect,
                           const std::vector<size_t>& probe_index,
                           const std::vector<double>& coarse_lx, size_t* counted = nullptr);

// The same figure from the probes' own reflected light, without the reflected light at every
// other point of the grid: `E_direct` per point of `grid`, `E_indirect_probe` and `coarse_lx` per
// probe, `max_indirect_lx` an upper bound of E_indirect anywhere on the grid. The surface's
// largest E is then at most the largest E_direct plus that bound, and at least the largest E
// known (E_direct anywhere, E at the probes). A probe whose E is at least 1 % of the upper value
// counts by its own E; a darker one's figure is at most its difference over max(E, 1 % of the
// lower value). Where no dark probe's can exceed the largest bright probe's, the floor does not
// change the largest, and the figure is patch_size_estimate's, to the bit (`exact`). Otherwise
// the floor may decide it, and `figure` is an upper bound of patch_size_estimate's (infinite
// where a dark probe's E and that floor are both 0): the figure itself needs every point.
struct ProbeFigure {
  double figure = 0.0;
  bool exact = true;
};
ProbeFigure patch_size_estimate_at_probes(const geometry::SurfaceGrid& grid,
                                          const std::vector<double>& E_direct,
                                          const std::vector<size_t>& probe_index,
                                          const std::vector<double>& E_indirect_probe,
                                          const std::vector<double>& coarse_lx,
                                          double max_indirect_lx);

// d2 of the estimate: the largest |E_ind(2h) - E_ind(4h)| over the probes of one surface,
// relative to the same denominators as patch_size_estimate (E at h), `coarse_lx` and
// `coarser_lx` per probe.
double coarse_level_difference(const geometry::SurfaceGrid& grid, const std::vector<double>& E,
                               const std::vector<size_t>& probe_index,
                               const std::vector<double>& coarse_lx,
                               const std::vector<double>& coarser_lx);

// Surface `s`'s estimate (every part the plan states) from its grid, E and E_indirect at every
// point (the same scale as the inputs' lx: both maintained, or both initial).
SurfaceEstimate estimate_surface(const geometry::SurfaceGrid& grid, const std::vector<double>& E,
                                 const std::vector<double>& E_indirect,
                                 const DirectEstimateInputs& direct,
                                 const IndirectEstimateInputs& indirect, size_t s);

// Fills results.plan.promise, .estimates and the indirect run's estimate (report/plan_text.h
// words them: a note per surface, a warning per surface whose estimate exceeds the promise).
// Needs E, E_direct and E_indirect of every surface (maintained).
void estimate_errors(Results& results, const DirectEstimateInputs& direct,
                     const IndirectEstimateInputs& indirect);

}  // namespace luxgrid::calc
