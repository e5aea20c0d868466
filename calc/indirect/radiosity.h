#pragma once
// Interreflection between patches: form factors and the radiosity solve, seeded by the first
// bounce (the VPL fluxes). Everything is in lumens per patch.
//
// Formulation (shooting form factors, flux units): F[j -> i] is the fraction of the light leaving
// patch j that lands on patch i, computed at j's centroid with the exact polygon form factor of
// i (near: within far_ratio x D_i / 2), the point kernel on i's quarters extrapolated to the
// patch (Richardson, between far_ratio x D_i / 2 and far_ratio x D_i; form_factor.h) or the point
// kernel on i (far), times the fraction of i visible from there. In a closed
// room each source's factors sum to 1 (the patches tile j's hemisphere); they are renormalised to 1
// (a factor per source, FormFactorMatrix::source_scale) so that no
// light is created or lost by discretisation or visibility sampling, which matters at high
// reflectance: a row-sum error e changes the converged total by about rho e / (1 - rho), 19 e at
// rho = 0.95. The largest correction is reported. A room with openings renormalises each source
// to 1 minus the form factor from its centroid to the openings (PatchMesh::escape_fraction): that
// share leaves the room.
//
// Solver: Jacobi on the bounce series, Delta_1 = rho D, Delta_k+1 = rho (F^T Delta_k), Phi = sum
// of Delta_k. Each sweep is exactly one more reflection, so `bounces: N` means exactly N
// reflections (N = 1 is the seed's one-bounce model), which Gauss-Seidel and Southwell shooting
// cannot promise. A sweep is one dense matrix-vector product (parallel, rows in order, the
// coplanar blocks skipped), so even 4000 patches cost ~5 ms per bounce. For `auto`, the ratio r_k =
// |Delta_k+1| / |Delta_k| tends to the dominant eigenvalue (exactly rho in a closed room of uniform
// rho); once it is stable the remaining bounces are a geometric series whose sum Delta_k r / (1 -
// r) is added (the "ambient" tail of Cohen et al. 1988), so rho = 0.95 converges in tens of sweeps,
// not hundreds.
#include <functional>
#include <span>
#include <vector>

#include "calc/indirect/clustered.h"
#include "calc/indirect/form_factor.h"
#include "calc/indirect/limits.h"
#include "calc/indirect/patches.h"
#include "geometry/visibility.h"
#include "util/large_buffer.h"

namespace luxgrid::calc::indirect {

// Dense form-factor matrix of one room's patches, stored so that row i holds F[j -> i] for all j
// (the "gather" layout: incident flux on i = row i . exitant flux).
struct FormFactorMatrix {
  size_t begin = 0, n = 0;  // patches [begin, begin + n) of the mesh
  // n x n, unnormalised: F[j -> i] = gather[i * n + j] x source_scale[j] (use at(i, j)), a view
  // of the matrix's own storage (allocate_gather; moving the matrix keeps it valid). The
  // renormalisation is a factor per source applied to the flux vector in each sweep, not a pass
  // over the matrix: the float entries then sum (in double) to exactly 1 / scale per source, so
  // the float matrix conserves the flux to double precision over any number of bounces.
  std::span<float> gather;
  std::vector<double>
      source_scale;  // per source j: kept_j / sum_i gather[i * n + j] (1 if not renormalised)
  double at(size_t i, size_t j) const {
    return static_cast<double>(gather[i * n + j]) * (source_scale.empty() ? 1.0 : source_scale[j]);
  }
  // Row i's entries j in [zero_begin[i], zero_end[i]) are 0: the patches coplanar with i and
  // next to it in the mesh (its face: the whole floor for a floor patch). The sweeps skip them,
  // about a third of the matrix in a flat room.
  std::vector<size_t> zero_begin, zero_end;
  double max_row_correction = 0.0;  // largest |kept_j - sum_i F[j -> i]| before renormalisation
  bool renormalised = true;

  // n x n entries for `gather`, uninitialised: form_factors writes every row.
  void allocate_gather() {
    storage_ = LargeBuffer<float>::uninitialised(n * n);
    gather = storage_.span();
  }

 private:
  LargeBuffer<float> storage_;  // a large matrix: in huge pages (util/large_buffer.h)
};

// `far_ratio`: the point kernel is used when the distance between centroids exceeds far_ratio x
// the receiving patch's diameter, its quarters (extrapolated) beyond half that, the exact formula
// closer (infinity: always exact). Rows of the gather layout are filled in parallel; each
// receiver takes the sources in tiles, and a tile wholly far and in front (most of a big room)
// in one branch-free loop. `renormalise`: scale each source to its kept fraction
// (patches.h: 1 in a closed room). Throws CalculationError naming the room index when the matrix
// would exceed kMaxFormFactorMatrixBytes (limits.h), before allocating it.
FormFactorMatrix form_factors(const PatchMesh& mesh, int room,
                              const geometry::Visibility* visibility, double far_ratio,
                              bool renormalise = true);

struct RadiosityResult {
  std::vector<double> exitant_flux_lm;  // per patch of the room (index i - begin)
  int bounces_run = 0;                  // reflections computed explicitly (sweeps + 1)
  bool tail_added = false;              // geometric remainder added (auto mode)
  double residual = 0.0;  // flux not accounted for, relative to the total: the next bounce's
                          // share for fixed N; the tail's estimated error for auto
  std::vector<double> bounce_flux_lm;  // |Delta_k| for k = 1..bounces_run
};

// `bounces` = 0: auto, until the remaining flux < tolerance x total (with the geometric tail);
// N >= 1: exactly N reflections. `max_bounces` caps auto mode (rho = 1 never converges); the
// residual then says how much was left. Throws CalculationError for N or max_bounces above
// kMaxBounces (limits.h): the solve always ends.
RadiosityResult solve_radiosity(const FormFactorMatrix& F, const std::vector<double>& reflectance,
                                const std::vector<double>& incident_flux_lm, int bounces,
                                double tolerance, int max_bounces = kMaxBounces);
// The same series over the clustered transfer of a large unobstructed room (clustered.h).
RadiosityResult solve_radiosity(const ClusteredTransfer& T, const std::vector<double>& reflectance,
                                const std::vector<double>& incident_flux_lm, int bounces,
                                double tolerance, int max_bounces = kMaxBounces);

// The bounce series itself, over any transfer: transfer(delta, received) sets received[i] to the
// flux landing on patch i when each patch j sends out delta[j] (renormalised). Both
// solve_radiosity overloads are this with their operator, so the series, the stopping rule and
// the tail exist once.
using BounceTransfer =
    std::function<void(const std::vector<double>& delta, std::vector<double>& received)>;
RadiosityResult solve_bounce_series(size_t n, const BounceTransfer& transfer,
                                    const std::vector<double>& reflectance,
                                    const std::vector<double>& incident_flux_lm, int bounces,
                                    double tolerance, int max_bounces = kMaxBounces);

}  // namespace luxgrid::calc::indirect
