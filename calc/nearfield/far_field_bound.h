#pragma once
// The near/far decision by an error bound (docs/nearfield.md): for one emitter (photometry +
// opening + TILT, in its own frame), a map over directions of the distance beyond which the
// far-field point model I(w) cos / d^2 is within a tolerance of the near-field integral.
//
// Why a map and not a rule: the point model's error at distance d is the difference between
// the intensity at the centre direction and its average over the opening's angular footprint
// (half-width ~ D / 2d), plus the cos / d^2 variation across the opening. For a smooth panel
// that is well below 1 % from 3-4 D; for a coarse table with a kink (8 C planes 45 degrees apart,
// bilinear between them) the footprint straddles the kink out to 10 D and more. The map is
// measured, not modelled: near field (the quality's rung) against far field along rays at growing
// distance, so it sees what the table actually does.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "photometry/intensity_distribution.h"
#include "util/robust_math.h"

namespace luxgrid::nearfield {

struct Emitter;
struct Model;

// What each quality promises against `reference` (docs/project-format.md): the tolerance the map
// is built for. Other rungs used with near_field "auto" get the standard promise.
inline constexpr double kStandardPromise = 0.01;  // relative
inline constexpr double kHighPromise = 0.003;     // relative
double promised_tolerance(const Model& near_model);

// The far field must meet the promise divided by this along the sampled rays. The samples sit
// on the kinks (the worst directions, see kGammaSamples), the blend only mixes values that are
// within the promise, and the near rung's own error is 1.2e-4 of the cell maximum on tables
// (docs/accuracy.md): 1.25 leaves 0.2 % of the 1 % for the ladder step and the rest. The
// price of more is steep: a bilinear table's kink makes the point model's error fall only as
// 1 / d (the footprint's half-width D / 2d times the slope change), so halving the target
// doubles the near-field distance in those directions (measured: Mirel C0 gamma 35, 3.1 % at
// 10 D, 1.6 % at 20 D, 0.79 % at 40 D).
inline constexpr double kBoundSafetyFactor = 1.25;

// Distances (x D, D = the opening's largest dimension) the search tries: a geometric ladder.
// Below 2 D the point model is never within 1 % for an opening seen face-on at a tilt (the
// cos / d^2 variation alone is ~ (D / 2d)^2 ~ 6 %), so the ladder starts there; beyond 48 D a
// direction still failing is left to the near field at every distance (the plan says so).
inline constexpr double kLadderStart = 2.0;  // x D
inline constexpr double kLadderRatio = 1.2;
inline constexpr int kLadderRungs = 19;  // 2 D x 1.2^18 = 53 D

// The far weight rises from 0 at d_far(w) to 1 at kBlendWidth x d_far(w) (smoothstep: value
// and slope continuous, so no seam; inside the band the far field is already within tolerance).
inline constexpr double kBlendWidth = 1.25;

// Receivers dimmer than this fraction of the emitter's peak illuminance at the same distance
// (I_max / d^2) are held to an absolute error of tolerance x that floor instead of a relative
// one: the promise covers points brighter than 1 % of a surface's maximum (docs/accuracy.md), and a
// direction at the dark edge of a beam would otherwise ask for the near field out to any
// distance for a value nobody reads. 1e-3 leaves a factor 10 to the 1 % line.
inline constexpr double kDimFloor = 1e-3;

// A direction failing out to the ladder's end keeps the near field at every distance.
inline constexpr float kNearEverywhere = 1e6f;  // x D

// Direction grid of the map in the luminaire frame: gamma from the emitting axis (0 = straight
// out of the opening), C the azimuth. 5 degrees in gamma and 7.5 in C put a sample on every
// 5-degree gamma line and every C plane of 7.5, 15, 22.5, 45 or 90 degrees spacing, where tables
// have their kinks; the dilation covers kinks near and between samples.
inline constexpr int kGammaSamples = 37;  // 0..180 degrees step 5
inline constexpr int kCSamples = 48;      // 0..352.5 degrees step 7.5

// What a run asks of the map: for every direction sample, the farthest distance (x D) at which a
// receiver of the scene lies in a direction interpolated from it (0: no receiver does). The
// weights of a pair read only the four samples around its direction (bilinear), and those read
// their neighbours' measurements up to kDilationReach samples away, so a sample no receiver
// reaches this way need not be measured, and one whose receivers are all nearer than some rung
// need not be measured beyond it. build_far_field_bound measures exactly that (docs/nearfield.md,
// "Only what the scene asks").
class MapDemand {
 public:
  MapDemand();
  // A receiver at `distance_over_D` in the unit direction `local_dir` of the luminaire frame, as
  // FarFieldBound::weights will be asked for it; `fixed_rule`: the fixed rule may serve it
  // (nearfield::fixed_rule_may_serve), so the map's fixed-rule distances are read there too.
  void add(const Vec3& local_dir, double distance_over_D, bool fixed_rule = true);
  // Both demands (the larger reach per sample).
  void merge(const MapDemand& other);
  // Per sample (gamma row-major, kCSamples per row): the farthest receiver (x D), 0 if none; and
  // the farthest the fixed rule may serve.
  const std::vector<float>& reach_over_D() const { return reach_; }
  const std::vector<float>& fixed_reach_over_D() const { return fixed_reach_; }
  std::size_t receivers() const { return receivers_; }

 private:
  std::vector<float> reach_, fixed_reach_;
  std::size_t receivers_ = 0;
};

struct FarFieldBound {
  double tolerance = kStandardPromise;  // the promise it was built for
  double largest_dimension_m = 0.0;
  // d_far / D per sample (gamma row-major, kCSamples per row) after dilation: each sample also
  // carries what its neighbours (up to 3 samples away) need, scaled by how far the opening's
  // footprint reaches (far_field_bound.cpp), so a kink near a sample is charged to it too.
  std::vector<float> d_far_over_D;
  // The same for the fixed rule (fixed_rule.h): d_fixed / D beyond which the fixed rule is
  // within the promise of the quality's rung, never beyond d_far (the far field is cheaper).
  std::vector<float> d_fixed_over_D;
  // 1 / d_far_over_D and 1 / d_fixed_over_D per sample (what the interpolation reads: the same
  // doubles, made once by build_far_field_bound); empty: computed at each look-up.
  std::vector<double> inv_far_over_D, inv_fixed_over_D;
  bool near_everywhere_somewhere = false;  // some direction failed out to the ladder's end
  // The fixed rule's summary for the plan (undilated samples).
  double fixed_median_over_D = 0.0, fixed_max_over_D = 0.0;
  // For the plan: the range and where the largest distance sits.
  double min_over_D = 0.0, max_over_D = 0.0, median_over_D = 0.0;
  double worst_c_deg = 0.0, worst_gamma_deg = 0.0;
  double worst_gradient_per_deg = 0.0;  // |grad I| / I there, relative per degree (the "why")
  // The plan's error estimate for the pairs these models serve: the largest relative error the
  // far field (the fixed rule) showed against the near rung at the distance chosen for each
  // sampled direction, over the five receiver normals (dimmer than the floor: relative to it).
  // At most tolerance / kBoundSafetyFactor by construction; the measured value is what the plan
  // quotes.
  double far_error_measured = 0.0;
  double fixed_error_measured = 0.0;
  // Beyond this distance (x D) every direction is past its blend band: the far field alone, and
  // weights() answers without locating the direction in the map. kNearEverywhere when some
  // direction keeps the near field at every distance.
  double far_everywhere_over_D = 0.0;
  // Built for a MapDemand: the samples measured (read by the scene's pairs or by their
  // dilation), of all kGammaSamples x kCSamples; directions whose receivers are all nearer than
  // the distance the far field would need (near field out to the farthest of them: `capped`).
  // The summary above is over the samples the scene's pairs read.
  bool restricted = false;
  int samples_measured = kGammaSamples * kCSamples;
  int samples_read = kGammaSamples * kCSamples;        // of them, read by the scene's pairs
  int fixed_samples_read = kGammaSamples * kCSamples;  // read for the fixed rule
  int samples_capped = 0;                              // of those, capped
  double capped_reach_over_D = 0.0;                    // their farthest receiver
  // Read samples whose distance the table's bound (table_far_bound.h) raised above the measured.
  int samples_raised_by_table = 0;

  // d_far(w) / D for a unit direction in the luminaire frame, bilinear between samples (so the
  // far weight is continuous across directions too).
  double distance_over_D(const Vec3& local_dir) const;
  // d_fixed(w) / D, interpolated the same way.
  double fixed_distance_over_D(const Vec3& local_dir) const;
  // Both weights of a receiver at distance `distance_m` along local direction `local_dir`, from
  // one interpolation: `far` rises from 0 at d_far to 1 at kBlendWidth x d_far; `fixed` rises from
  // 0 at d_fixed to 1 at kBlendWidth x d_fixed (the share of the fixed rule in the near part).
  struct Weights {
    double far = 0.0;
    double fixed = 0.0;
    // Where the two bands start along this direction (m); beyond far_everywhere_over_D the
    // largest d_far of any direction stands in for the far one (an upper bound of it).
    double far_start_m = 0.0, fixed_start_m = 0.0;
  };
  Weights weights(const Vec3& local_dir, double distance_m) const;
  // The same from the direction's photometric angles as photometry::angles_of gives them (the
  // same weights: calc/nearfield/switch_run.h computes the angles of four pairs at once).
  Weights weights(const photometry::PhotometricAngles& angles, double distance_m) const;

 private:
  // Both of the above: the angles when given, else those of `local_dir`.
  Weights weights_at(const Vec3& local_dir, const photometry::PhotometricAngles* angles,
                     double distance_m) const;
};

// Builds the map for `emitter` (its own frame is read from emitter.rotation, so the map is the
// same for every pose) against `near_model`, for the promise `tolerance`. Cost: about 2 x 10^5
// near-field evaluations worst case, in parallel on oneTBB's workers (tens to hundreds of ms per
// distinct emitter; `luxgrid --threads` limits them).
// With `demand`, only the samples it reads, each out to the farthest receiver that reads it
// (the rest is never asked): a sample whose far field fails out to that receiver keeps the near
// field at every distance, so weights() of a pair the demand holds gives a far weight no larger
// than the whole map's; a sample passing within it finds the rung the whole map finds where
// the error falls with distance, as the ladder assumes.
// Samples that measure the same (map_symmetry.h: the pole rows, and a direction and its mirror
// image where the emitter is its own) are measured once; `share_mirror_images` false measures
// every sample itself (for the tests that compare the two).
std::shared_ptr<const FarFieldBound> build_far_field_bound(const Emitter& emitter,
                                                           const Model& near_model,
                                                           double tolerance,
                                                           const MapDemand* demand = nullptr,
                                                           bool share_mirror_images = true);

// What the plan reports of one map: its outcome and cause as codes, with the numbers they quote
// (report/plan_text.h words them). The codes are the decisions summarize() takes from the map.
struct FarFieldBoundSummary {
  // Which directions the summary is over: the whole map, or the samples the scene's points lie in
  // (a MapDemand), some of them capped (the near field out to their farthest point).
  enum class Scope { whole_map, demand, demand_capped };
  enum class Outcome {
    near_at_every_point,        // every demanded direction keeps the near field to its farthest
    no_point_in_reach,          // a demand with no sample read
    near_everywhere_somewhere,  // some direction keeps the near field at every distance
    near_out_to,                // every direction has a far-field distance
  };
  // Why the distance is as large as it is: up to 8 D the opening's geometry alone (slanted
  // receivers) explains it (a Lambertian square measures 7.2 D); beyond, the table does, by a
  // sharp beam (the intensity changing faster than 5 %/deg) or by kinks and curvature.
  enum class Cause { smooth_distribution, sharp_beam, kinks };
  enum class FixedRule { serves_none, not_every_direction, within };
  Scope scope = Scope::whole_map;
  Outcome outcome = Outcome::near_out_to;
  Cause cause = Cause::smooth_distribution;
  FixedRule fixed_rule = FixedRule::within;
  int samples_all = kGammaSamples * kCSamples;
  int samples_read = 0, samples_capped = 0;
  double capped_reach_over_D = 0.0;
  double tolerance = 0.0, largest_dimension_m = 0.0;
  double min_over_D = 0.0, max_over_D = 0.0, median_over_D = 0.0;
  double worst_c_deg = 0.0, worst_gamma_deg = 0.0, worst_gradient_per_deg = 0.0;
  double far_error_measured = 0.0;
  double fixed_median_over_D = 0.0, fixed_max_over_D = 0.0, fixed_error_measured = 0.0;
};
FarFieldBoundSummary summarize(const FarFieldBound& bound);

}  // namespace luxgrid::nearfield
