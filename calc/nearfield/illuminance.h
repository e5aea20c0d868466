#pragma once
// The one entry point the rest of luxgrid calls for direct light from one luminaire at one
// receiver point, optionally with occlusion (geometry/visibility.h, tested per quadrature node:
// soft shadows), and the near/far switch (an error bound per emitter, far_field_bound.h, or the
// five-times rule).
#include <cstdint>
#include <string>

#include "calc/nearfield/emitter.h"
#include "calc/nearfield/far_field_bound.h"
#include "calc/nearfield/receiver_kernel.h"
#include "geometry/visibility.h"

namespace luxgrid::nearfield {

struct TableRungScratch;  // table_rung_scratch.h

enum class ModelKind {
  far_field,           // point at the centroid (quality draft)
  paper_cubature,      // Luksch et al. 2020 as published ("near_field_model": "paper")
  subdivided,          // every fan triangle split into 4^level with the paper's rule (Eq. 10)
  lambert_subdivided,  // same split, exact projected solid angle and product average
  adaptive,            // adaptive rung, local tolerance `tolerance`
  standard,            // quality standard: within 1 % of the reference on the paper's protocol
  high,                // quality high: the table rung for a measured table (exact to its
                       // interpolant), else the adaptive rung at 1e-3
  reference,           // converged area-form integrator, tolerance `tolerance` (quality reference)
};
// The baselines of [Luksch2020, Sec. 4] (structured sampling, the most representative point,
// Monte Carlo) are research models of the accuracy study, not rungs: study/baselines.h.

struct Model {
  ModelKind kind = ModelKind::standard;
  int level = 0;           // subdivision k (4^k triangles per fan triangle)
  double tolerance = 0.0;  // relative; adaptive and reference (0 = the model's default)

  static Model far_field() { return {ModelKind::far_field}; }
  static Model paper_cubature() { return {ModelKind::paper_cubature}; }
  static Model subdivided(int k) { return {ModelKind::subdivided, k}; }
  static Model lambert_subdivided(int k) { return {ModelKind::lambert_subdivided, k}; }
  static Model adaptive(double rel_tol) { return {ModelKind::adaptive, 0, rel_tol}; }
  static Model standard() { return {ModelKind::standard}; }
  static Model high() { return {ModelKind::high}; }
  static Model reference(double rel_tol = 0.0) { return {ModelKind::reference, 0, rel_tol}; }
};

// A short name for tables and results ("paper", "lambert k=2", "adaptive 1e-3", ...).
std::string to_string(const Model& model);

// Illuminance (lx) at `point` with unit `normal` from the emitter, by `model`. Always finite and
// >= 0. Light reaches the receiver only from above its horizon; the opening emits from both
// faces with L = I / (A |cos|), so upward intensity reaches receivers behind the opening.
// `occluder` (optional): the paper cubature, subdivided, adaptive, standard and reference models
// test visibility per node / sample (soft shadows); the far field tests
// the one segment from the opening's centroid (hard shadows). nullptr costs nothing.
// `scratch`: the table rung's buffers (table_rung_scratch.h), the caller's, one per thread, so
// that a loop over many pairs allocates them once; null: the call's own.
double illuminance(const Emitter& emitter, const Vec3& point, const Vec3& normal,
                   const Model& model, const geometry::Visibility* occluder = nullptr,
                   TableRungScratch* scratch = nullptr);

// The same for any receiver (receiver_kernel.h): a plane is the function above; cylindrical and
// semi-cylindrical illuminance integrate the receiver's weight over the opening with the same
// ladder: the far field (point kernel at the centroid); standard and high on a measured table
// (no occluder) the table rung; every other case the area-form adaptive cubature
// (reference_illuminance) at the rung's tolerance: standard kStandardAreaFormRelTol, high and
// adaptive 1e-3 (or the model's), reference 1e-4 (or the model's). The Lambert-exact rungs
// (two-kernel, Duffy-sinh, paper, subdivided) rest on closed forms of the planar kernel and have
// no cylindrical form; the paper and subdivided models get the area form at 1e-3.
double illuminance(const Emitter& emitter, const Vec3& point, const Receiver& receiver,
                   const Model& model, const geometry::Visibility* occluder = nullptr,
                   TableRungScratch* scratch = nullptr);

// The weights of the automatic switch at `point`. `far`: the far-field model's, blended so the
// near/far switch draws no seam on an isolux plot (smoothstep: continuous value and slope). With
// an error bound (emitter.far_bound, far_field_bound.h, what calc/direct attaches for standard
// and high): 0 nearer than the direction's d_far, 1 beyond kBlendWidth x d_far. Without one, the
// five-times rule: 0 below kBlendStart x D, 1 beyond kBlendEnd x D (D = largest dimension).
inline constexpr double kBlendStart = 4.0;  // x largest dimension
inline constexpr double kBlendEnd = 6.0;    // x largest dimension
// `fixed`: the share of the fixed rule (fixed_rule.h) in the near part: 0 nearer than the
// direction's d_fixed, 1 beyond kBlendWidth x d_fixed (far_field_bound.h). Without a bound (or
// without rule nodes) `fixed` is 0: the near model alone. With a bound, the distances the two bands
// start at along the pair's direction and the pair's distance (for estimated_pair_error); 0
// otherwise.
struct SwitchWeights {
  double far = 0.0;
  double fixed = 0.0;
  double far_start_m = 0.0, fixed_start_m = 0.0, distance_m = 0.0;
};
SwitchWeights switch_weights(const Emitter& emitter, const Vec3& point);
// What switch_weights gives for an emitter with an error bound, from the bound's weights of the
// pair at distance `distance_m` (> 0): the one place that turns the one into the other (for
// switch_weights and calc/nearfield/switch_run.h).
SwitchWeights switch_weights_of_bound(const Emitter& emitter, const FarFieldBound::Weights& w,
                                      double distance_m);

// The plan's estimate of a pair's relative error from the models `w` mixes (calc/plan_estimates.h):
// the far field's measured error at d_far (FarFieldBound::far_error_measured) falling as
// d_far / d beyond it (a kink's error falls as 1 / d, the opening's geometry as 1 / d^2:
// far_field_bound.h), times its weight; the same for the fixed rule's share of the near part.
// 0 without a bound (the near rung is what the map measures against).
double estimated_pair_error(const Emitter& emitter, const SwitchWeights& w);

// Whether the fixed rule may serve a pair of this receiver (where the map allows it): planar
// receivers only (the map measures it on planes, and a cylinder's weight sin(eps) vanishes along
// the axis, where a few nodes are far off: 3 % under a panel), and not where the table rung is in
// closed form along its rays without an occluder (it then costs about what the fixed rule does
// and is exact in gamma, where the fixed rule is only within the promise: 0.25 % off under a
// panel at 2.6 D, docs/nearfield.md).
bool fixed_rule_may_serve(const Emitter& emitter, const Receiver& receiver, const Model& near_model,
                          const geometry::Visibility* occluder);

// settings.near_field: auto (blend by switch_weights), always (near model everywhere),
// never (far field everywhere).
enum class NearFieldSwitch { automatic, always, never };

// What calc/direct calls: `near_model` is the quality's rung (Model::standard() for standard).
// With automatic, the far field alone is evaluated beyond the band, the near model alone inside
// it, both within it (weights from switch_weights); with an error bound the near part is the
// fixed rule where the bound allows it, blended into the near model over its own band.
// `occluder` as in illuminance(): the far-field part uses the centroid segment; `scratch` too.
double hybrid_illuminance(const Emitter& emitter, const Vec3& point, const Vec3& normal,
                          const Model& near_model,
                          NearFieldSwitch mode = NearFieldSwitch::automatic,
                          const geometry::Visibility* occluder = nullptr,
                          TableRungScratch* scratch = nullptr);
// The same for any receiver: cylindrical and semi-cylindrical illuminance take the same
// near/far decision as planar. `used`, when given, receives the weights the pair was computed
// with (far 1 for never, 0 for always; fixed 0 off planar receivers), so a caller counting pairs
// per model does not take the decision twice.
double hybrid_illuminance(const Emitter& emitter, const Vec3& point, const Receiver& receiver,
                          const Model& near_model,
                          NearFieldSwitch mode = NearFieldSwitch::automatic,
                          const geometry::Visibility* occluder = nullptr,
                          SwitchWeights* used = nullptr, TableRungScratch* scratch = nullptr);
// The same with mode automatic and the pair's switch_weights already computed (`weights`: what
// switch_weights(emitter, point) gives, e.g. from switch_weights_run for a run of emitters).
double hybrid_illuminance_weighted(const Emitter& emitter, const Vec3& point,
                                   const Receiver& receiver, const Model& near_model,
                                   const SwitchWeights& weights,
                                   const geometry::Visibility* occluder = nullptr,
                                   SwitchWeights* used = nullptr,
                                   TableRungScratch* scratch = nullptr);

}  // namespace luxgrid::nearfield
