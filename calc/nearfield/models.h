#pragma once
// The emitter models of the near-field ladder, each a plain function of (emitter, receiver point,
// receiver unit normal) -> illuminance in lux. Most callers use illuminance() in
// calc/nearfield/illuminance.h instead; these are public for tests, benchmarks and the accuracy
// study (study/). `occluder` (optional, geometry/visibility.h) multiplies each quadrature node's
// radiance by its visibility; nullptr (the default) is free.
#include <cstdint>

#include "calc/nearfield/emitter.h"
#include "calc/nearfield/fan_sample.h"
#include "calc/nearfield/receiver_kernel.h"
#include "geometry/visibility.h"

namespace luxgrid::nearfield {

struct TableRungScratch;  // table_rung_scratch.h

// The inverse-square law of a point source at `source` (m, world) with the distribution turned
// into the world by `world_to_local` (R^T of the luminaire's rotation R): E = I(-w) g(w) / d^2,
// w the unit direction from the receiver at `point` to the source and g the receiver's weight
// (receiver_kernel.h; cos(theta_x) for a plane). Finite and >= 0; a receiver at the source
// itself gets 0 (the point model has no answer there). The one copy of the far-field formula:
// the far-field model below and calc/direct's luminaire form call it.
double point_source_illuminance(const photometry::IntensityDistribution& distribution,
                                const glm::dmat3& world_to_local, const Vec3& source,
                                const Vec3& point, const Receiver& receiver);
// The same formula with any lookup `intensity(local, inv_length) -> cd` of the direction
// `local` in the luminaire frame, whose length is 1 / inv_length: a distribution needs the unit
// vector local x inv_length (the function above passes it); the texture's coordinates do not
// depend on the length (photometry/distribution_texture.h), so calc/direct.cpp's far-field loop
// looks `local` up as it is, and the lookup does not wait for the square root and the division.
// The formula in two steps, which calc/direct.cpp's far-field loop takes one at a time for a run
// of points (every point's geometry, then one batch lookup, then every pair's illuminance):
// the pair's geometry (r = source - point, d^2, the receiver's weight of the unit direction; at
// d^2 = 0 the direction is NaN and the weight 0 or NaN), and E = I weight / d^2 from the
// intensity I (cd) of the direction -r in the luminaire frame, where d^2 > 0 and weight > 0
// (else 0, which the callers add as +0).
struct FarPair {
  Vec3 r;
  double d2, inv_d, weight;
};
inline FarPair far_pair(const Vec3& source, const Vec3& point, const Receiver& receiver) {
  FarPair p;
  p.r = source - point;
  p.d2 = glm::dot(p.r, p.r);
  p.inv_d = 1.0 / std::sqrt(p.d2);
  p.weight = receiver_weight(receiver, p.r * p.inv_d);
  return p;
}
inline bool far_pair_lit(double d2, double weight) { return d2 > 0.0 && weight > 0.0; }
inline double far_pair_illuminance(double intensity_cd, double weight, double d2) {
  return sanitize_illuminance(intensity_cd * weight / d2);
}
template <class Lookup>
inline double point_source_illuminance_with(const Lookup& intensity,
                                            const glm::dmat3& world_to_local, const Vec3& source,
                                            const Vec3& point, const Receiver& receiver) {
  const FarPair p = far_pair(source, point, receiver);
  if (!far_pair_lit(p.d2, p.weight)) return 0.0;
  return far_pair_illuminance(intensity(world_to_local * -p.r, p.inv_d), p.weight, p.d2);
}

// Far-field point at the emitter centroid: E = I(-w) cos(theta_x) / d^2, finite and >= 0.
double far_field_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal);
// The same for any receiver (receiver_kernel.h): E = I(-w) g(w) / d^2, g the receiver's weight.
double far_field_illuminance(const Emitter& e, const Vec3& point, const Receiver& receiver);

// The Luksch et al. 2020 cubature exactly as published (Sec. 5, Eq. 10):
//   E = sum over fan triangles of mean(L) * mean(G) * |triangle|  (Van Oosterom-Strackee).
// `shift_m` is the horizon epsilon shift; pass horizon_shift_m(e) (the default below) — other
// values exist for the hard-case tests. Not sanitized: returns NaN where the method breaks.
double paper_cubature_raw(const Emitter& e, const Vec3& point, const Vec3& normal, double shift_m,
                          const geometry::Visibility* occluder = nullptr);
double paper_cubature_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal,
                                  const geometry::Visibility* occluder = nullptr);

// How one (sub)triangle of the fan is integrated.
enum class TriangleRule {
  paper,            // Eq. 10: mean(L) mean(G) Omega, Omega by Van Oosterom-Strackee
  lambert_mean,     // exact projected solid angle (Lambert) times mean(L): exact for uniform L
  lambert_product,  // exact projected solid angle times the L average that is exact when L and
                    // the area-form weight cos_r cos_e / d^2 are both linear over the triangle
  two_kernel,       // I fitted as a cos_e + b over the triangle's vertices, each term integrated
                    // exactly: a * projected solid angle + b * integral of cos_r / d^2 dA
                    // (exact for Lambertian and for isotropic emitters)
};

// Every fan triangle split into n x n similar triangles in the emitter plane (n = 2^k gives the
// issue's "subdivided k times", 4^k triangles), each integrated by `rule`.
double subdivided_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal, int n,
                              TriangleRule rule, const geometry::Visibility* occluder = nullptr);

// Adaptive rung (two-kernel rule unless given): globally adaptive, the triangle whose estimate
// differs most from the sum of its four children's (edge-midpoint split) is split first, until
// the summed differences are below rel_tol * E or a budget (20000 lookups) is spent. Returns
// the children's sums; `error_lx` (optional) receives the summed |differences|. With an
// occluder, a cell whose six nodes (corners and edge midpoints) disagree on visibility carries
// at least half its value as error indicator, so the shadow edge is refined until it converges.
double adaptive_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal, double rel_tol,
                            double* error_lx = nullptr,
                            const geometry::Visibility* occluder = nullptr);
// The same with a chosen rule; `samples` (optional) receives the number of intensity lookups.
double adaptive_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal, double rel_tol,
                            TriangleRule rule, double* error_lx, int* samples,
                            const geometry::Visibility* occluder = nullptr);

// The tolerance of standard's area-form tier (ladder.cpp) and of standard's cylindrical and
// semi-cylindrical illuminance where no table rung applies (illuminance.cpp): the 7-point rule's
// error estimate at 3e-3 kept every point above 1e-3 of the peak within 1 % (0.84 % worst, 10
// data sets of the paper's protocol).
inline constexpr double kStandardAreaFormRelTol = 3e-3;

// quality "standard": see docs/nearfield.md. Within 1 % of the reference on the paper's protocol.
// `scratch`: the table rung's buffers (table_rung_scratch.h); null: the call's own.
double standard_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal,
                            const geometry::Visibility* occluder = nullptr,
                            TableRungScratch* scratch = nullptr);

// The table rung (docs/nearfield.md, "The table rung"), calc/nearfield/table_cubature.cpp: for
// a distribution with a TableView (a type C table, possibly scaled), the area form in polar
// coordinates around the receiver's foot on the emitter plane, where the table's C and gamma
// lines are coordinate lines, with a 2 x 2 Gauss-Legendre rule on every table cell the emitter
// covers. Converges like a smooth integrand where the adaptive rungs meet kinks. Returns false
// (`lux` untouched) without a table view or for a point emitter.
// `scratch` (table_rung_scratch.h): the rung's buffers, the caller's, one per thread.
bool table_aligned_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal, double& lux,
                               TableRungScratch& scratch);
// The same for any receiver (receiver_kernel.h): the receiver's weight replaces cos_r at every
// node; a cylinder has no horizon, so its polygon is the whole opening.
bool table_aligned_illuminance(const Emitter& e, const Vec3& point, const Receiver& receiver,
                               double& lux, TableRungScratch& scratch);
// True when the table rung integrates a plane receiver with this normal (world) in closed form
// along each ray: a bilinear table and a normal along the opening's axis (a workplane under a
// ceiling luminaire, a floor, a ceiling). There it costs about what the fixed rule does.
bool table_rung_in_closed_form(const Emitter& e, const Vec3& normal);
// The table rung's light vector at `point` (world, lux): its nodes over the whole opening, each
// weighted by the unit direction to it instead of a receiver's cos_r. For a plane that sees the
// whole opening in front of it (no horizon clip) the rung's value is n . vector up to rounding,
// so one pass serves every such normal (the near/far map's five receivers). False as
// table_aligned_illuminance.
bool table_light_vector(const Emitter& e, const Vec3& point, Vec3& light_vector_lx,
                        TableRungScratch& scratch);

// Exact illuminance from a uniform (Lambertian) emitter of luminance `luminance_cd_m2`:
// Lambert's polygon formula E = L/2 |n . sum_edges theta g| on the horizon-clipped polygon.
// Only the emitting side is lit. No horizon shift.
double lambert_uniform_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal,
                                   double luminance_cd_m2);

struct ReferenceResult {
  double illuminance_lx = 0.0;
  double error_estimate_lx = 0.0;  // sum over leaf triangles of |coarse - fine|
  std::int64_t evaluations = 0;    // intensity lookups
  bool converged = false;          // error estimate <= rel_tol * E (or abs floor) reached
};

// Converging reference for any distribution: the area form (Eq. 1), E = (1/A) integral of
// I(-w) cos_r / d^2 dA over the horizon-clipped polygon, by globally adaptive cubature on
// triangles (degree-5 7-point rule, 4-way splits of the triangle with the largest error first)
// until the error estimate is below rel_tol * E. Same horizon shift as the other models, so all
// models integrate the same regularised problem. Independent of the solid-angle machinery.
// With an occluder, each sample's integrand is multiplied by its visibility (the 7-point rule's
// error estimate sees the discontinuity and refines along the shadow edge).
ReferenceResult reference_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal,
                                      double rel_tol = 1e-7,
                                      std::int64_t max_evaluations = 4'000'000,
                                      const geometry::Visibility* occluder = nullptr);
// The same for any receiver (receiver_kernel.h): the integrand's cos_r becomes the receiver's
// weight g(w); a cylinder has no horizon, so the fan covers the whole opening.
ReferenceResult reference_illuminance(const Emitter& e, const Vec3& point, const Receiver& receiver,
                                      double rel_tol = 1e-7,
                                      std::int64_t max_evaluations = 4'000'000,
                                      const geometry::Visibility* occluder = nullptr);

}  // namespace luxgrid::nearfield
