#include "report/plan_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "calc/plan_estimates.h"
#include "report/daylight_plan_text.h"
#include "util/format.h"

namespace luxgrid::report {

namespace {

// "1.6 %": two digits, as the estimates are quoted.
// An infinite estimate (bounces that absorb no light never fade) is "unbounded", not "inf %".
std::string percent2(double fraction) {
  return std::isfinite(fraction) ? format_double("%.2g %%", 100.0 * fraction) : "unbounded";
}
// Three digits: a texture's bound just above its limit must not print as the limit.
std::string percent3(double fraction) { return format_double("%.3g %%", 100.0 * fraction); }

std::string count_text(size_t n) { return std::to_string(n); }

// "\"mirel\" (luminaire 3)" or "\"mirel\" (48 luminaires)".
std::string group_text(const calc::LuminaireGroup& g) {
  const std::string who = g.luminaires == 1 ? g.label : count_text(g.luminaires) + " luminaires";
  return "\"" + g.photometry + "\" (" + who + ")";
}

std::string plural(size_t n, const std::string& one, const std::string& many) {
  return count_text(n) + " " + (n == 1 ? one : many);
}

// "a: 0.05 of its output", "b: 250 lm", "c: photometry \"em\"": as the project gave it.
std::string emergency_output_text(const calc::EmergencyOutputNote& o) {
  const std::string what = !o.photometry.empty() ? "photometry \"" + o.photometry + "\""
                           : o.flux_lm > 0.0     ? number_text(o.flux_lm) + " lm"
                                                 : number_text(o.factor) + " of its output";
  return o.luminaire + ": " + what;
}

// What the mesh is refined for (calc::refinement_target): "standard's promise", or reference's
// convergence target with its figure.
std::string refinement_target_text(calc::Quality quality) {
  if (quality == calc::Quality::reference)
    return "reference's convergence target of " + percent2(calc::refinement_target(quality));
  return std::string(calc::to_string(quality)) + "'s promise";
}

std::string refinement_why(const calc::PatchRefinement& r, calc::Quality quality) {
  return "the patch-size difference at " + format_double("%.3g", r.from_m) + " m (to the mesh at " +
         format_double("%.3g", 2.0 * r.from_m) + " m), " + format_double("%.2g", 100 * r.estimate) +
         " % on surface '" + r.surface + "', is above half of " + refinement_target_text(quality);
}

std::string work_over_limit_text(const calc::PatchRefinement& r) {
  return "a mesh at " + format_double("%.3g", r.to_m) + " m would cost " +
         format_double("%.2g", r.work_pairs) +
         " pairs and links (a dense room's form-factor pairs, a pair counting 8 where rays are "
         "traced; a clustered room's links), above the limit of " +
         format_double("%.2g", r.work_limit_pairs);
}

// A refinement that took place: the whole mesh at `to_m`, or the mesh cut to `to_m` around probes.
bool refined(const calc::PatchRefinement& r) {
  return r.outcome == calc::PatchRefinement::Outcome::refined ||
         r.outcome == calc::PatchRefinement::Outcome::local;
}

std::string refinement_text(const calc::PatchRefinement& r, calc::Quality quality) {
  if (r.outcome == calc::PatchRefinement::Outcome::local)
    return "indirect: patches cut to " + format_double("%.3g", r.to_m) + " m within " +
           format_double("%.3g", r.reach_m) + " m of " +
           plural(r.local_points, "probe point", "probe points") + " (" +
           plural(r.patches_cut, "patch", "patches") + " of " + format_double("%.3g", r.from_m) +
           " m cut into quarters) where the difference asks for it: " + refinement_why(r, quality) +
           ", and " + work_over_limit_text(r);
  return "indirect: patch size refined from " + format_double("%.3g", r.from_m) + " m to " +
         format_double("%.3g", r.to_m) + " m: " + refinement_why(r, quality);
}

// A refinement the work limit or the patch budget stopped (PatchRefinement's outcomes other than
// `refined` and `local`).
std::string refinement_stop_text(const calc::PatchRefinement& r, calc::Quality quality) {
  if (r.outcome == calc::PatchRefinement::Outcome::work_over_limit)
    return "indirect: " + refinement_why(r, quality) + ", but " + work_over_limit_text(r) +
           "; the patch size stays " + format_double("%.3g", r.from_m) + " m";
  return "indirect: " + refinement_why(r, quality) + ", but a mesh at " +
         format_double("%.3g", r.to_m) + " m exceeds the patch budget (" + r.budget_error + ")";
}

// The largest total estimate over the surfaces (direct light, patch size and bounces, as the
// promise counts them), -1 where the estimates were not made or one of them is missing (the far
// field at every distance, reflected light not estimated).
double worst_total_estimate(const calc::Plan& plan) {
  if (!plan.errors_estimated || plan.estimates.empty()) return -1.0;
  double worst = 0.0;
  for (const auto& est : plan.estimates) {
    if (est.direct < 0.0 || est.patch_size < 0.0) return -1.0;
    worst = std::max(worst, est.total());
  }
  return worst;
}

// A stopped refinement is a warning unless the plan's estimate of the mesh that stayed is within
// the quality's target on every surface: the refinement chooses on the patch-size difference d1
// alone, against half the target (the first-order estimate, the side a choice errs on), while the
// plan's estimate extrapolates d1 with the order it measured and adds the direct light's and the
// bounces' (docs/accuracy.md). Where that total is within the target a finer mesh was wanted, not
// needed, and a warning would cry wolf (tests/rooms/ushape at standard: wall 2's d1 0.80 %, its
// total estimate 0.40 %, measured 0.12 % against the room's reference). Where it is not, the
// estimate's own warning says so too.
bool refinement_stop_harmless(const calc::Plan& plan) {
  const double worst = worst_total_estimate(plan);
  const double target = calc::refinement_target(plan.quality);
  return target > 0.0 && worst >= 0.0 && worst <= target;
}

std::string refinement_stop_harmless_text(const calc::Plan& plan) {
  return "the plan's estimate there (the patch size's extrapolated with the order measured on "
         "three meshes, with the direct light's and the bounces') is at most " +
         format_double("%.2g", 100 * worst_total_estimate(plan)) + " % on every surface, within " +
         refinement_target_text(plan.quality);
}

}  // namespace

std::string promise_text(calc::Quality q) {
  switch (q) {
    case calc::Quality::draft:
      return "draft promises no accuracy (far field at every distance, one bounce)";
    case calc::Quality::reference:
      return "reference is the yardstick the other qualities are measured against";
    case calc::Quality::standard:
    case calc::Quality::high: break;
  }
  return std::string(calc::to_string(q)) + " promises within " + percent2(calc::promised_error(q)) +
         " of reference at every point brighter than 1 % of its surface's maximum";
}

std::string far_field_bound_text(const nearfield::FarFieldBoundSummary& b) {
  using S = nearfield::FarFieldBoundSummary;
  char buf[448];
  char fixed[256];
  char scope[320] = "";
  const int all = b.samples_all;
  if (b.scope == S::Scope::demand_capped)
    std::snprintf(scope, sizeof scope,
                  "; measured over the %d of %d directions the scene's points lie in, each out "
                  "to its farthest point (%d of them keep the near field out to it, up to %.1f "
                  "D)",
                  b.samples_read, all, b.samples_capped, b.capped_reach_over_D);
  else if (b.scope == S::Scope::demand)
    std::snprintf(scope, sizeof scope,
                  "; measured over the %d of %d directions the scene's points lie in, each out "
                  "to its farthest point",
                  b.samples_read, all);
  const char* why =
      b.cause == S::Cause::smooth_distribution ? "smooth distribution (geometry of the opening)"
      : b.cause == S::Cause::sharp_beam        ? "sharp beam"
                                               : "kinks or curvature between measured angles";
  switch (b.outcome) {
    case S::Outcome::near_at_every_point:
      std::snprintf(buf, sizeof buf,
                    "near field at every point: in each of the %d of %d directions the scene's "
                    "points lie in the far field is not within %.2g %% out to the farthest of them "
                    "(up to %.1f D, D = %.2f m)",
                    b.samples_read, all, 100 * b.tolerance, b.capped_reach_over_D,
                    b.largest_dimension_m);
      break;
    case S::Outcome::no_point_in_reach:
      std::snprintf(buf, sizeof buf, "no point of the scene in reach (D = %.2f m)",
                    b.largest_dimension_m);
      return buf;
    case S::Outcome::near_everywhere_somewhere:
      std::snprintf(buf, sizeof buf,
                    "%s: near field at every distance at C %.1f gamma %.0f deg, from %.1f D "
                    "elsewhere (median %.1f D, D = %.2f m)%s; far field within %.2g %% beyond "
                    "(measured at most %.2g %%)",
                    why, b.worst_c_deg, b.worst_gamma_deg, b.min_over_D, b.median_over_D,
                    b.largest_dimension_m, scope, 100 * b.tolerance, 100 * b.far_error_measured);
      break;
    case S::Outcome::near_out_to:
      std::snprintf(buf, sizeof buf,
                    "%s: near field out to %.1f D (at C %.1f gamma %.0f deg, intensity changing "
                    "%.1f %%/deg), %.1f D at least, median %.1f D (D = %.2f m)%s; far field within "
                    "%.2g %% beyond (measured at most %.2g %%)",
                    why, b.max_over_D, b.worst_c_deg, b.worst_gamma_deg,
                    100 * b.worst_gradient_per_deg, b.min_over_D, b.median_over_D,
                    b.largest_dimension_m, scope, 100 * b.tolerance, 100 * b.far_error_measured);
      break;
  }
  switch (b.fixed_rule) {
    case S::FixedRule::serves_none:
      std::snprintf(fixed, sizeof fixed,
                    "; the fixed rule serves none of the scene's pairs (cylinders, or planes "
                    "facing the opening's axis, where the table rung is in closed form)");
      break;
    case S::FixedRule::not_every_direction:
      std::snprintf(fixed, sizeof fixed,
                    "; the fixed rule within %.2g %% beyond %.1f D (median), not at every "
                    "direction (measured at most %.2g %%)",
                    100 * b.tolerance, b.fixed_median_over_D, 100 * b.fixed_error_measured);
      break;
    case S::FixedRule::within:
      std::snprintf(fixed, sizeof fixed,
                    "; the fixed rule within %.2g %% beyond %.1f D (median), %.1f D at most "
                    "(measured at most %.2g %%)",
                    100 * b.tolerance, b.fixed_median_over_D, b.fixed_max_over_D,
                    100 * b.fixed_error_measured);
      break;
  }
  return std::string(buf) + fixed;
}

std::string intensity_lookup_text(const calc::IntensityLookupChoice& c) {
  using Kind = calc::IntensityLookupChoice::Kind;
  const std::string grid = count_text(c.c_cells) + "x" + count_text(c.gamma_cells);
  const std::string quality = calc::to_string(c.quality);
  const std::string probed = "1/" + count_text(c.probe_fraction) + " of its texels";
  switch (c.kind) {
    case Kind::analytic: return "the distribution itself (analytic: exact, no table to look up)";
    case Kind::table_by_quality:
      return "the exact table (quality " + quality + " always looks the table up)";
    case Kind::table_few_pairs:
      return "the exact table (" + count_text(c.pairs) +
             " luminaire-point pairs: too few for an intensity texture to pay for its building)";
    case Kind::table_float_range:
      return "the exact table (its intensities exceed the range of a texture's float texels)";
    case Kind::table_probe_deviates:
      return "the exact table (the intensity texture " + grid + " deviates from it by " +
             percent3(c.deviation) + " on " + probed + "; limit at " + quality + ": " +
             percent3(c.limit) + ")";
    case Kind::texture_draft:
      return "intensity texture " + grid + ", within about " + percent3(c.deviation) +
             " of the table (measured on " + probed + "; draft takes it without a limit)";
    case Kind::texture_within:
      return "intensity texture " + grid + ", within " + percent3(c.deviation) +
             " of the table (limit at " + quality + ": " + percent3(c.limit) + ")";
    case Kind::table_texture_deviates:
      return "the exact table (the intensity texture " + grid + " deviates up to " +
             percent3(c.deviation) + " from it; limit at " + quality + ": " + percent3(c.limit) +
             ")";
  }
  return "?";
}

std::string indirect_note_text(const calc::indirect::IndirectNote& n) {
  using Kind = calc::indirect::IndirectNote::Kind;
  const std::string from_to = "patch size raised from " + format_double("%.3g", n.from_m) +
                              " m to " + format_double("%.3g", n.to_m) + " m to stay within ";
  const std::string total =
      count_text(n.limit) + " patches in all " + (n.clustered_limit ? "clustered rooms" : "rooms");
  switch (n.kind) {
    case Kind::budget_above_limit:
      return "indirect: the budget of " + count_text(n.asked) +
             " patches per room is above the limit of " + count_text(n.limit) +
             " (a form-factor matrix of " + count_text(n.matrix_mb) + " MB); " +
             count_text(n.limit) + " used";
    case Kind::room_raised:
      return "room '" + n.room + "': " + from_to + count_text(n.budget) + " patches per room";
    case Kind::rooms_raised: return "all " + count_text(n.rooms) + " rooms: " + from_to + total;
    case Kind::rooms_raised_meshed: return "all rooms: " + from_to + total;
    case Kind::room_raised_meshed:
      return "room '" + n.room + "': " + from_to + count_text(n.budget) + " patches";
    case Kind::luminaire_outside:
      return n.luminaire + ": not inside any room, its light is not reflected";
    case Kind::opening_outside: {
      char buf[256];
      std::snprintf(buf, sizeof buf,
                    "%s: %.4g %% of its luminous opening (%s %.4g x %.4g m) lies outside its room "
                    "or inside an obstacle; that light does not enter the room: %.6g lm of %.6g "
                    "lm enter",
                    n.luminaire.c_str(), 100.0 * n.fraction, n.disk ? "disk" : "rectangle",
                    n.length_m, n.width_m, n.entering_lm, n.flux_lm);
      std::string out = buf;
      for (size_t k = 0; k < n.rooms_entered.size(); ++k)
        out += (k == 0 ? " room '" : ", '") + n.rooms_entered[k] + "'";
      return out;
    }
    case Kind::clustered_wider:
      return "indirect: room '" + n.room + "': clustered transfer with the opening ratio " +
             format_double("%.3g", n.opening) + " instead of " +
             format_double("%.3g", n.quality_opening) + ": the links of " + count_text(n.patches) +
             " patches at the quality's ratio would exceed " + count_text(n.limit_mb) +
             " MB; the reflected light near the room's edges may then be off by more than the "
             "quality's figures";
  }
  return "?";
}

std::string indirect_decision_text(const calc::indirect::IndirectDecision& d) {
  using R = calc::indirect::IndirectReason;
  const std::string estimate = format_double("%.4g", d.estimate_lx) + " lx";
  switch (d.reason) {
    case R::off_in_settings: return "skipped: indirect is off in the settings";
    case R::no_reflectance: return "skipped: all reflectances are 0";
    case R::no_luminaires: return "skipped: no luminaires";
    case R::forced_on:
      return "on (forced by the settings); integrating-sphere estimate " + estimate;
    case R::observers:
      return "on: observers surface '" + d.observers_surface +
             "' needs reflected light for UGR's background luminance; integrating-sphere "
             "estimate " +
             estimate;
    case R::below_threshold:
      return "skipped: integrating-sphere estimate " + estimate +
             " is below 1 % of the mean direct illuminance " +
             format_double("%.4g", d.mean_direct_lx) + " lx";
    case R::estimate:
      return "on: integrating-sphere estimate " + estimate +
             (d.sampled ? " against a mean direct illuminance of " +
                              format_double("%.4g", d.mean_direct_lx) + " lx"
                        : std::string());
  }
  return "?";
}

std::string direct_text(const calc::Plan& plan) {
  const calc::DirectCounts& c = plan.direct_counts;
  const std::string model = nearfield::to_string(plan.near_model);
  std::string out;
  switch (plan.near_switch) {
    case nearfield::NearFieldSwitch::never: out = "far-field point model everywhere"; break;
    case nearfield::NearFieldSwitch::always:
      out = "near-field model " + model + " at every distance";
      break;
    case nearfield::NearFieldSwitch::automatic:
      if (!plan.near_far.empty()) {
        out = "hybrid by an error bound (near-field " + model +
              " wherever the far-field point model is not within the quality's promise, measured "
              "per emitter and direction; the fixed rule of a few nodes across the opening where "
              "it is within the promise and the far field is not; each blended over 1.25 x its "
              "distance)";
      } else {
        out = "hybrid by the five-times rule (near-field " + model + " closer than " +
              count_text(static_cast<size_t>(nearfield::kBlendStart)) +
              " x the emitter size, far-field beyond " +
              count_text(static_cast<size_t>(nearfield::kBlendEnd)) + " x, blended between)";
      }
      break;
  }
  out += ": " + count_text(c.near) + " luminaire-point pairs near-field, " + count_text(c.blended) +
         " blended, " + count_text(c.far) + " far-field, " + count_text(c.point_sources) +
         " from point sources (exact point model)";
  if (c.fixed_rule + c.fixed_blended > 0)
    out += "; of the near-field and blended pairs " + count_text(c.fixed_rule) +
           " by the fixed rule, " + count_text(c.fixed_blended) +
           " blending it into the near-field model";
  for (const auto& e : plan.near_far)
    out += "; " + group_text(e.group) + ": " + far_field_bound_text(e.bound);
  if (!plan.intensity_lookups.empty()) {
    out += "; far-field pairs and the first bounce look intensities up in:";
    for (size_t k = 0; k < plan.intensity_lookups.size(); ++k)
      out += (k == 0 ? " " : "; ") + group_text(plan.intensity_lookups[k].group) + ": " +
             intensity_lookup_text(plan.intensity_lookups[k].choice);
  }
  if (plan.pairs_unreachable > 0)
    out += "; " + count_text(plan.pairs_unreachable) +
           " luminaire-point pairs not computed: the luminaire's opening lies in none of the "
           "point's rooms, and light does not pass through a room's walls, floor or ceiling";
  return out;
}

namespace {
std::string indirect_run_text(const calc::IndirectRunPlan& r) {
  const std::string what = r.bounces_asked == 1 ? "one bounce (RSM-style)"
                           : r.bounces_asked > 1
                               ? count_text(static_cast<size_t>(r.bounces_asked)) + " bounces"
                               : "converged interreflection (" +
                                     count_text(static_cast<size_t>(r.bounces_run)) + " bounces" +
                                     (r.tail_added ? " + geometric tail" : "") + ")";
  std::string out = what + ": " + count_text(r.patches) + " patches of " +
                    format_double("%.3g", r.patch_size_m) + " m, " + count_text(r.vpls) +
                    " virtual point lights, residual " +
                    (std::isfinite(r.residual) ? format_double("%.2g", r.residual) : "unbounded");
  if (r.split_patches)
    out += "; " + count_text(r.split_patches) +
           " patches cut into quarters where the light jumps between neighbours";
  if (r.refined_patches)
    out += "; " + count_text(r.refined_patches) + " patches seen from closer than " +
           format_double("%.3g", r.subcell_reach) + " diameters refined into " +
           count_text(static_cast<size_t>(r.subcells_per_side)) + " x " +
           count_text(static_cast<size_t>(r.subcells_per_side)) + " cells";
  out += "; direct flux on room faces " + format_double("%.6g", r.received_flux_lm) + " lm of " +
         format_double("%.6g", r.emitted_flux_lm) + " lm emitted into the rooms";
  if (r.part_outside)
    out += " (of " + format_double("%.6g", r.luminaire_flux_lm) + " lm from the whole openings)";
  if (r.clustered_rooms)
    out += "; clustered transfer (" + count_text(r.clustered_rooms) + " room" +
           (r.clustered_rooms == 1 ? "" : "s") + ", " + count_text(r.clustered_links) + " links)";
  if (r.visibility) out += "; visibility: AABB tree of room and obstacle faces";
  if (r.obstacles)
    out += "; " + count_text(r.obstacles) + " obstacle" + (r.obstacles == 1 ? "" : "s") +
           " reflect and shade";
  return out;
}
}  // namespace

std::string indirect_text(const calc::Plan& plan) {
  std::string out = plan.emergency_direct_only
                        ? "off: the emergency scene counts direct light only (EN 1838)"
                    : plan.indirect_run ? indirect_run_text(*plan.indirect_run)
                                        : indirect_decision_text(plan.indirect_decision);
  if (plan.indirect_run && plan.indirect_run->estimated) {
    const calc::IndirectRunPlan& r = *plan.indirect_run;
    if (!(r.coarse_patch_size_m > 0.0)) {
      // `draft` solves one mesh: nothing to compare it with.
      out +=
          "; estimated error: patch size not estimated (one mesh solved), bounces not followed "
          "up to " +
          percent2(r.worst_bounces) + " of E";
    } else {
      char buf[256];
      std::snprintf(buf, sizeof buf,
                    "; estimated error: patch size %.3g m up to %s of E (extrapolated from %.3g m "
                    "and %.3g m at up to %zu probe points per surface), bounces not followed up "
                    "to %s of E",
                    r.patch_size_m, percent2(r.worst_patch_size).c_str(), r.coarse_patch_size_m,
                    r.coarser_patch_size_m, r.probe_points_per_surface,
                    percent2(r.worst_bounces).c_str());
      out += buf;
    }
  }
  return out;
}

std::string visibility_text(const calc::Plan& plan) {
  const calc::VisibilityDecision& v = plan.visibility;
  if (!v.on)
    return v.no_rooms ? "off: no rooms and no obstacles, nothing can block light"
                      : "off: convex room, no obstacles, every luminaire inside";
  std::vector<std::string> why;
  if (v.obstacles > 0) why.push_back(plural(v.obstacles, "obstacle", "obstacles"));
  if (v.rooms > 1) why.push_back(count_text(v.rooms) + " rooms");
  for (const auto& r : v.non_convex_rooms) why.push_back("non-convex room '" + r + "'");
  if (v.luminaires_outside == 1) why.push_back(v.first_outside + " outside every room");
  if (v.luminaires_outside > 1)
    why.push_back(count_text(v.luminaires_outside) + " luminaires outside every room");
  if (v.openings_reaching == 1)
    why.push_back("the opening of " + v.first_reaching + " reaches outside its room");
  if (v.openings_reaching > 1)
    why.push_back("the openings of " + count_text(v.openings_reaching) +
                  " luminaires reach outside their rooms");
  if (v.points_outside > 0)
    why.push_back(plural(v.points_outside, "surface point", "surface points") +
                  " outside every room");
  std::string out = "on:";
  for (size_t i = 0; i < why.size(); ++i) out += (i ? ", " : " ") + why[i];
  return out +
         "; near-field pairs test visibility per quadrature node (soft shadows of area "
         "luminaires), far-field pairs from the centre of the opening";
}

std::string scene_note_text(const calc::SceneNote& note) {
  switch (note.kind) {
    case calc::SceneNote::Kind::emergency_scene: {
      std::string outputs;
      for (const auto& o : note.outputs)
        outputs += (outputs.empty() ? "" : "; ") + emergency_output_text(o);
      if (note.luminaires > note.outputs.size()) outputs += "; ...";
      return "emergency scene (EN 1838): direct light only, from the " +
             count_text(note.luminaires) + " of " + count_text(note.of_luminaires) +
             " luminaires with an emergency entry, at their emergency output (" + outputs + ")";
    }
    case calc::SceneNote::Kind::observers_left_out:
      return "emergency scene: " + count_text(note.observers) +
             " observers surface(s) left out (UGR is not an emergency lighting quantity)";
  }
  return {};
}

std::vector<std::string> plan_notes(const calc::Plan& plan) {
  // The daylight scene: its own notes, then its reflected light's and estimates as below.
  std::vector<std::string> notes =
      plan.daylight ? daylight_notes(plan) : std::vector<std::string>{};
  if (!plan.daylight && plan.near_switch_reason == calc::NearSwitchReason::draft_quality)
    notes.push_back("quality draft: far-field point model at every distance");
  for (const auto& n : plan.scene_notes) notes.push_back(scene_note_text(n));
  for (const auto& r : plan.refinements)
    if (refined(r)) notes.push_back(refinement_text(r, plan.quality));
  if (refinement_stop_harmless(plan))
    for (const auto& r : plan.refinements)
      if (!refined(r))
        notes.push_back(refinement_stop_text(r, plan.quality) + "; " +
                        refinement_stop_harmless_text(plan));
  for (const auto& n : plan.indirect_notes) notes.push_back(indirect_note_text(n));
  if (!plan.errors_estimated) return notes;
  const bool ran = plan.indirect_run.has_value();
  for (const auto& est : plan.estimates) {
    std::string line =
        "estimated error at surface '" + est.surface + "': " + percent2(est.total()) +
        (plan.daylight ? " (sky and ground " : " (direct ") +
        (est.direct < 0.0 ? "not estimated: far field at every distance" : percent2(est.direct));
    if (ran)
      line += (est.patch_size < 0.0 ? std::string(", patch size not estimated (one mesh solved)")
                                    : ", patch size " + percent2(est.patch_size) + " on " +
                                          count_text(est.probe_points) + " probe points") +
              ", bounces " + percent2(est.bounces);
    line += ")";
    if (plan.promise > 0.0)
      line += " against the promise of " + percent2(plan.promise);
    else if (calc::refinement_target(plan.quality) > 0.0)
      line += " against " + refinement_target_text(plan.quality);
    notes.push_back(line);
  }
  notes.push_back(
      "textures: none (one reflectance per face, no texture maps), so no texture-resolution error");
  return notes;
}

std::vector<std::string> plan_warnings(const calc::Plan& plan) {
  std::vector<std::string> warnings =
      plan.daylight ? daylight_warnings(plan) : std::vector<std::string>{};
  if (!refinement_stop_harmless(plan))
    for (const auto& r : plan.refinements)
      if (!refined(r)) warnings.push_back(refinement_stop_text(r, plan.quality));
  for (const auto& w : plan.indirect_warnings) warnings.push_back(indirect_note_text(w));
  const double promise = plan.promise;
  const std::string quality = calc::to_string(plan.quality);
  for (const auto& est : plan.estimates) {
    if (promise > 0.0 && est.direct < 0.0)
      warnings.push_back("surface '" + est.surface +
                         "': the far field at every distance (near_field never) has no error "
                         "estimate; " +
                         quality + "'s promise of " + percent2(promise) + " is not checked");
    if (promise > 0.0 && est.total() > promise) {
      const char* largest =
          est.direct >= std::max(est.patch_size, est.bounces)
              ? (plan.daylight ? "the sky and ground integration" : "the far-field decision")
          : est.patch_size >= est.bounces ? "the interreflection patch size"
                                          : "the bounces not followed";
      const std::string error = std::isfinite(est.total())
                                    ? percent2(est.total()) + " exceeds "
                                    : std::string(
                                          "is unbounded (the reflectances absorb no "
                                          "light, so the bounces never fade), above ");
      warnings.push_back("surface '" + est.surface + "': the plan's estimated error " + error +
                         quality + "'s promise of " + percent2(promise) +
                         " (largest part: " + largest + ")");
    }
  }
  return warnings;
}

std::string plan_summary(const calc::Plan& plan) {
  if (plan.daylight) return daylight_summary(plan);
  const calc::DirectCounts& c = plan.direct_counts;
  std::string direct;
  switch (plan.near_switch) {
    case nearfield::NearFieldSwitch::never: direct = "far field everywhere"; break;
    case nearfield::NearFieldSwitch::always:
      direct = "near field (" + nearfield::to_string(plan.near_model) + ") everywhere";
      break;
    case nearfield::NearFieldSwitch::automatic:
      direct = std::string(plan.near_far.empty() ? "hybrid by the five-times rule"
                                                 : "hybrid by an error bound") +
               " (" + nearfield::to_string(plan.near_model) + ")";
      break;
  }
  const size_t pairs = c.near + c.blended + c.far + c.point_sources;
  direct += ", " + count_text(c.near) + " of " + count_text(pairs) + " pairs near-field";
  std::string indirect;
  if (plan.emergency_direct_only)
    indirect = "off (emergency scene)";
  else if (plan.indirect_run)
    indirect = (plan.indirect_run->bounces_asked == 1 ? std::string("one bounce")
                : plan.indirect_run->bounces_asked > 1
                    ? count_text(static_cast<size_t>(plan.indirect_run->bounces_asked)) + " bounces"
                    : std::string("converged")) +
               ", " + count_text(plan.indirect_run->patches) + " patches";
  else
    indirect = indirect_decision_text(plan.indirect_decision);
  std::string out = "direct: " + direct + "; indirect: " + indirect +
                    "; visibility: " + (plan.visibility.on ? "on" : "off");
  double worst = 0.0;
  for (const auto& e : plan.estimates) worst = std::max(worst, e.total());
  if (!plan.estimates.empty()) {
    out += "; estimated error up to " + percent2(worst);
    if (plan.promise > 0.0) out += " (promise " + percent2(plan.promise) + ")";
  }
  return out;
}

}  // namespace luxgrid::report
