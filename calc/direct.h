#pragma once
// Direct illuminance on every point of every calculation surface, summed over luminaires,
// in parallel over points (oneTBB).
#include <functional>
#include <vector>

#include "calc/direct_reach.h"
#include "calc/plan.h"
#include "calc/scene.h"
#include "util/simd.h"

namespace luxgrid::calc {

using Progress = std::function<void(double fraction_done)>;

// Far-field point model of a luminaire at its pose: E = I(w) cos(theta) / d^2, w the direction
// from the luminaire to the point in the luminaire's frame, theta the angle of incidence at the
// receiver (nearfield::point_source_illuminance, the one copy of the formula). Zero for light
// arriving from behind the receiver or at the luminaire itself. Finite and >= 0.
double far_field_illuminance(const Luminaire& lum, const Vec3& point, const Vec3& normal);

// What a point of a grid measures. Horizontal and vertical are planes whose normals the loader
// has set; a half cylinder faces the normal the loader set to its `facing` direction.
nearfield::Receiver receiver_of(geometry::Quantity q, const Vec3& normal);

// E_direct of the points [begin, end) of grid (a plane receiver per point, inactive points
// skipped) from the luminaires (indices into emitters) when every pair is the far-field point
// model without a visibility test, into E[begin, end): per point the sum over the luminaires in
// their order of nearfield::point_source_illuminance, to the bit (the texture's lookups of a run
// at once, structure of arrays). At most kFarFieldRun points. One version per target
// (util/simd.h's LUXGRID_MULTIVERSION), each callable by name.
// Points per run: the run's sums stay in L1 while every luminaire passes over it, and
// neighbouring points read neighbouring texels of the luminaire's texture.
inline constexpr size_t kFarFieldRun = 64;
LUXGRID_MULTIVERSION_DECLARE(void, far_field_run,
                             (const std::vector<nearfield::Emitter>& emitters,
                              const std::vector<uint32_t>& luminaires,
                              const geometry::SurfaceGrid& grid, size_t begin, size_t end,
                              std::vector<double>& E))

// The emitters of all luminaires, built once per run (calc/nearfield/emitter.h).
std::vector<nearfield::Emitter> make_emitters(const Scene& scene);

// E_direct per point of `grid` (same order as grid.points): for each luminaire the plan's model
// (far field, near field, or the five-times-rule blend of both) with the plan's visibility test
// (when it has one): per quadrature node for the near-field models (soft shadows), from the
// opening's centre for the far field; inactive points get 0. The grid's quantity picks the
// receiver (nearfield/receiver_kernel.h): a plane on each point's normal, a cylinder, or a half
// cylinder facing the point's normal; every quantity takes the same near/far decision. `progress`
// may be empty; it is called from worker threads. `counts`, when given, is increased by the pairs
// each model served. `reach`, when given, limits each point to the luminaires of its zone, tested
// through the zone's visibility tree (calc/direct_reach.h); the luminaires left out cannot
// reach the point, so the sums are the same, added in the same order.
// each model served, and `estimated_error_lx` receives per point the plan's estimate of the direct
// light's error (lx, sum over pairs of E_pair x nearfield::estimated_pair_error).
std::vector<double> direct_illuminance(const Plan& plan,
                                       const std::vector<nearfield::Emitter>& emitters,
                                       const geometry::SurfaceGrid& grid,
                                       const Progress& progress = {},
                                       DirectCounts* counts = nullptr,
                                       const GridReach* reach = nullptr,
                                       std::vector<double>* estimated_error_lx = nullptr);

}  // namespace luxgrid::calc
