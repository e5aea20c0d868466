#pragma once
// The plan's estimate of its own error (docs/accuracy.md, "The plan's own estimate"): what each
// quality promises, and per surface what each remaining approximation is estimated to cost,
// from measurements the run makes, not from constants:
//   - far field and fixed rule for a luminaire-point pair: the error the near/far map measured
//     at the distance it chose (nearfield/far_field_bound.h), falling as d_far / d beyond it,
//     weighted by each pair's share of the point's illuminance (nearfield::estimated_pair_error);
//   - the interreflection mesh's patch size h: the indirect illuminance at h against the same
//     room meshed at 2h, on a few probe points per surface. Patch-constant radiosity converges
//     at least linearly in h, so E(h) - E(0) ~ E(2h) - E(h): |E_ind(h) - E_ind(2h)| bounds the
//     error at h where the convergence is first order and overstates it where it is faster;
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

// Probe points per surface for the patch-size estimate: the coarse run gathers at these only,
// so it costs the coarse mesh (a quarter of the patches, 1/16 of the form factors) and little more.
inline constexpr size_t kProbePointsPerSurface = 48;

// Up to kProbePointsPerSurface active points of `grid`, evenly spread over its index order
// (rows of a grid), and the grid reduced to them.
std::vector<size_t> probe_points(const geometry::SurfaceGrid& grid);
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
  std::vector<std::vector<double>> coarse_lx;    // per surface: E_ind at 2h there, maintained lx
  // Not for the estimate: the reflected light leaving through openings (IndirectResult's), for
  // the daylight plan's balance.
  double escaped_flux_lm = 0.0;
};

// The patch-size estimate of one surface: the largest |E_ind(h) - E_ind(2h)| over its probe
// points, relative to the point's E (direct + indirect) but no less than 1 % of the surface's
// largest E, as the promise counts it. `E` and `E_indirect` per point of `grid`, `coarse_lx`
// per probe; `counted` (if not null) gets the number of probes that count.
double patch_size_estimate(const geometry::SurfaceGrid& grid, const std::vector<double>& E,
                           const std::vector<double>& E_indirect,
                           const std::vector<size_t>& probe_index,
                           const std::vector<double>& coarse_lx, size_t* counted = nullptr);

// The same figure from the probes' own reflected light, without the reflected light at every
// other point of the grid: `E_direct` per point of `grid`, `E_indirect_probe` and `coarse_lx` per
// probe, `max_indirect_lx` an upper bound of E_indirect anywhere on the grid. The surface's
// largest E is then at most the largest E_direct plus that bound; where every counted probe's E
// is at least 1 % of it, the floor cannot apply and the figure is patch_size_estimate's, to the
// bit. Returns -1 where a probe is darker (the floor may apply: the caller needs every point).
double patch_size_estimate_at_probes(const geometry::SurfaceGrid& grid,
                                     const std::vector<double>& E_direct,
                                     const std::vector<size_t>& probe_index,
                                     const std::vector<double>& E_indirect_probe,
                                     const std::vector<double>& coarse_lx, double max_indirect_lx);

// Fills results.plan.promise, .estimates and the indirect run's estimate (report/plan_text.h
// words them: a note per surface, a warning per surface whose estimate exceeds the promise).
// Needs E, E_direct and E_indirect of every surface (maintained).
void estimate_errors(Results& results, const DirectEstimateInputs& direct,
                     const IndirectEstimateInputs& indirect);

}  // namespace luxgrid::calc
