#include "report/plan_json.h"

#include <cmath>
#include <limits>

#include "report/json_fields.h"
#include "report/plan_text.h"

// The (de)serializers live in each type's namespace, where nlohmann::json finds them; the keys
// are the fields' names.
namespace luxgrid::nearfield {
NLOHMANN_JSON_SERIALIZE_ENUM(ModelKind, {{ModelKind::far_field, "far_field"},
                                         {ModelKind::paper_cubature, "paper_cubature"},
                                         {ModelKind::subdivided, "subdivided"},
                                         {ModelKind::lambert_subdivided, "lambert_subdivided"},
                                         {ModelKind::adaptive, "adaptive"},
                                         {ModelKind::standard, "standard"},
                                         {ModelKind::high, "high"},
                                         {ModelKind::reference, "reference"}})
NLOHMANN_JSON_SERIALIZE_ENUM(NearFieldSwitch, {{NearFieldSwitch::automatic, "automatic"},
                                               {NearFieldSwitch::always, "always"},
                                               {NearFieldSwitch::never, "never"}})
NLOHMANN_JSON_SERIALIZE_ENUM(FarFieldBoundSummary::Scope,
                             {{FarFieldBoundSummary::Scope::whole_map, "whole_map"},
                              {FarFieldBoundSummary::Scope::demand, "demand"},
                              {FarFieldBoundSummary::Scope::demand_capped, "demand_capped"}})
NLOHMANN_JSON_SERIALIZE_ENUM(
    FarFieldBoundSummary::Outcome,
    {{FarFieldBoundSummary::Outcome::near_at_every_point, "near_at_every_point"},
     {FarFieldBoundSummary::Outcome::no_point_in_reach, "no_point_in_reach"},
     {FarFieldBoundSummary::Outcome::near_everywhere_somewhere, "near_everywhere_somewhere"},
     {FarFieldBoundSummary::Outcome::near_out_to, "near_out_to"}})
NLOHMANN_JSON_SERIALIZE_ENUM(FarFieldBoundSummary::Cause,
                             {{FarFieldBoundSummary::Cause::smooth_distribution,
                               "smooth_distribution"},
                              {FarFieldBoundSummary::Cause::sharp_beam, "sharp_beam"},
                              {FarFieldBoundSummary::Cause::kinks, "kinks"}})
NLOHMANN_JSON_SERIALIZE_ENUM(FarFieldBoundSummary::FixedRule,
                             {{FarFieldBoundSummary::FixedRule::serves_none, "serves_none"},
                              {FarFieldBoundSummary::FixedRule::not_every_direction,
                               "not_every_direction"},
                              {FarFieldBoundSummary::FixedRule::within, "within"}})
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(FarFieldBoundSummary, scope, outcome, cause, fixed_rule,
                                   samples_all, samples_read, samples_capped, capped_reach_over_D,
                                   tolerance, largest_dimension_m, min_over_D, max_over_D,
                                   median_over_D, worst_c_deg, worst_gamma_deg,
                                   worst_gradient_per_deg, far_error_measured, fixed_median_over_D,
                                   fixed_max_over_D, fixed_error_measured)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(Model, kind, level, tolerance)
}  // namespace luxgrid::nearfield

namespace luxgrid::calc::indirect {
NLOHMANN_JSON_SERIALIZE_ENUM(IndirectNote::Kind,
                             {{IndirectNote::Kind::budget_above_limit, "budget_above_limit"},
                              {IndirectNote::Kind::room_raised, "room_raised"},
                              {IndirectNote::Kind::rooms_raised, "rooms_raised"},
                              {IndirectNote::Kind::rooms_raised_meshed, "rooms_raised_meshed"},
                              {IndirectNote::Kind::room_raised_meshed, "room_raised_meshed"},
                              {IndirectNote::Kind::luminaire_outside, "luminaire_outside"},
                              {IndirectNote::Kind::opening_outside, "opening_outside"},
                              {IndirectNote::Kind::clustered_wider, "clustered_wider"}})
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(IndirectNote, kind, room, luminaire, rooms_entered, rooms,
                                   budget, limit, asked, matrix_mb, patches, limit_mb,
                                   clustered_limit, disk, from_m, to_m, fraction, length_m, width_m,
                                   entering_lm, flux_lm, opening, quality_opening)
NLOHMANN_JSON_SERIALIZE_ENUM(IndirectReason, {{IndirectReason::off_in_settings, "off_in_settings"},
                                              {IndirectReason::no_reflectance, "no_reflectance"},
                                              {IndirectReason::no_luminaires, "no_luminaires"},
                                              {IndirectReason::forced_on, "forced_on"},
                                              {IndirectReason::observers, "observers"},
                                              {IndirectReason::below_threshold, "below_threshold"},
                                              {IndirectReason::estimate, "estimate"}})
}  // namespace luxgrid::calc::indirect

namespace luxgrid::calc {
NLOHMANN_JSON_SERIALIZE_ENUM(Quality, {{Quality::draft, "draft"},
                                       {Quality::standard, "standard"},
                                       {Quality::high, "high"},
                                       {Quality::reference, "reference"}})
NLOHMANN_JSON_SERIALIZE_ENUM(NearSwitchReason,
                             {{NearSwitchReason::draft_quality, "draft_quality"},
                              {NearSwitchReason::setting_never, "setting_never"},
                              {NearSwitchReason::setting_always, "setting_always"},
                              {NearSwitchReason::reference_quality, "reference_quality"},
                              {NearSwitchReason::automatic, "automatic"}})
NLOHMANN_JSON_SERIALIZE_ENUM(
    IntensityLookupChoice::Kind,
    {{IntensityLookupChoice::Kind::analytic, "analytic"},
     {IntensityLookupChoice::Kind::table_by_quality, "table_by_quality"},
     {IntensityLookupChoice::Kind::table_few_pairs, "table_few_pairs"},
     {IntensityLookupChoice::Kind::table_float_range, "table_float_range"},
     {IntensityLookupChoice::Kind::table_probe_deviates, "table_probe_deviates"},
     {IntensityLookupChoice::Kind::texture_draft, "texture_draft"},
     {IntensityLookupChoice::Kind::texture_within, "texture_within"},
     {IntensityLookupChoice::Kind::table_texture_deviates, "table_texture_deviates"}})
NLOHMANN_JSON_SERIALIZE_ENUM(PatchRefinement::Outcome,
                             {{PatchRefinement::Outcome::refined, "refined"},
                              {PatchRefinement::Outcome::work_over_limit, "work_over_limit"},
                              {PatchRefinement::Outcome::over_budget, "over_budget"},
                              {PatchRefinement::Outcome::local, "local"}})
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(DirectCounts, point_sources, far, near, blended, fixed_rule,
                                   fixed_blended)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LuminaireGroup, photometry, luminaires, label)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(NearFarPlan, group, bound)
// draft's texture limit is infinite (calc::texture_limit): JSON has no infinity, so it is left out
// and read back as +infinity, as put_finite/read_maybe_infinite below do for the plan's numbers.
void to_json(nlohmann::json& j, const IntensityLookupChoice& c) {
  j = {{"kind", c.kind},           {"quality", c.quality},
       {"c_cells", c.c_cells},     {"gamma_cells", c.gamma_cells},
       {"deviation", c.deviation}, {"probe_fraction", c.probe_fraction},
       {"pairs", c.pairs}};
  if (std::isfinite(c.limit)) j["limit"] = c.limit;
}
void from_json(const nlohmann::json& j, IntensityLookupChoice& c) {
  report::read_fields(j, "kind", c.kind, "quality", c.quality, "c_cells", c.c_cells, "gamma_cells",
                      c.gamma_cells, "deviation", c.deviation, "probe_fraction", c.probe_fraction,
                      "pairs", c.pairs);
  c.limit = j.contains("limit") && !j.at("limit").is_null()
                ? j.at("limit").get<double>()
                : std::numeric_limits<double>::infinity();
}
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(IntensityLookupPlan, group, choice)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(IndirectRunPlan, bounces_asked, bounces_run, tail_added, patches,
                                   patch_size_m, vpls, residual, refined_patches, split_patches,
                                   subcell_reach, subcells_per_side, received_flux_lm,
                                   emitted_flux_lm, luminaire_flux_lm, part_outside,
                                   clustered_rooms, clustered_links, visibility, obstacles,
                                   estimated, coarse_patch_size_m, coarser_patch_size_m,
                                   probe_points_per_surface, worst_patch_size, worst_bounces)
// A local step's own numbers are written for it alone (the other outcomes have none).
void to_json(nlohmann::json& j, const PatchRefinement& r) {
  j = {{"outcome", r.outcome},
       {"from_m", r.from_m},
       {"to_m", r.to_m},
       {"estimate", r.estimate},
       {"surface", r.surface},
       {"work_pairs", r.work_pairs},
       {"work_limit_pairs", r.work_limit_pairs},
       {"budget_error", r.budget_error}};
  if (r.outcome == PatchRefinement::Outcome::local) {
    j["local_points"] = r.local_points;
    j["reach_m"] = r.reach_m;
    j["patches_cut"] = r.patches_cut;
  }
}
void from_json(const nlohmann::json& j, PatchRefinement& r) {
  report::read_fields(j, "outcome", r.outcome, "from_m", r.from_m, "to_m", r.to_m, "estimate",
                      r.estimate, "surface", r.surface, "work_pairs", r.work_pairs,
                      "work_limit_pairs", r.work_limit_pairs, "budget_error", r.budget_error);
  if (r.outcome == PatchRefinement::Outcome::local)
    report::read_fields(j, "local_points", r.local_points, "reach_m", r.reach_m, "patches_cut",
                        r.patches_cut);
}
NLOHMANN_JSON_SERIALIZE_ENUM(SceneNote::Kind,
                             {{SceneNote::Kind::emergency_scene, "emergency_scene"},
                              {SceneNote::Kind::observers_left_out, "observers_left_out"}})
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(EmergencyOutputNote, luminaire, factor, flux_lm, photometry)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(SceneNote, kind, luminaires, of_luminaires, observers, outputs)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(VisibilityDecision, on, no_rooms, obstacles, rooms,
                                   non_convex_rooms, luminaires_outside, openings_reaching,
                                   first_outside, first_reaching, points_outside)
}  // namespace luxgrid::calc

namespace luxgrid::calc {
// The daylight scene's plan (calc/daylight_plan.h): every field by its name (a field a results.json
// written before it existed reads as its default).
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE_WITH_DEFAULT(
    DaylightPlan, sky, diffuse_horizontal_lx, ground_reflectance, has_sun, sun_altitude_deg,
    sun_azimuth_deg, sun_from_site, sky_integral_sr, sky_integral_error_sr, openings,
    glazed_openings, exterior_obstructions, sky_exact, ground_exact, relative_tolerance,
    sky_error_percent, ground_error_percent, evaluations, points_outside_rooms,
    internally_reflected, reflecting_surfaces, indirect_off, flux_entering_lm, flux_on_surfaces_lm,
    flux_escaping_lm, luminaires_left_out, direct_sun, sun_reflected, direct_normal_lx,
    sun_shadow_samples, sun_flux_entering_lm, sun_flux_on_surfaces_lm, sun_flux_escaping_lm,
    sun_patches, sun_patch_size_m)
}  // namespace luxgrid::calc

namespace luxgrid::report {

namespace {
using nlohmann::json;

// results.json holds no null (docs/reliability.md): a value that is not there is left out.
// A number that may be infinite (the integrating-sphere estimate of a room whose reflectance is
// 1, the residual of bounces that absorb nothing): JSON has no infinity, so it is left out and
// read back as +infinity.
void put_finite(json& j, const char* key, double v) {
  if (std::isfinite(v)) j[key] = v;
}
double read_maybe_infinite(const json& j, const char* key) {
  return j.contains(key) && !j.at(key).is_null() ? j.at(key).get<double>()
                                                 : std::numeric_limits<double>::infinity();
}
// An estimate's part: left out where it was not estimated (negative in calc::SurfaceEstimate)
// and where it is unbounded (bounces that absorb nothing: `unbounded` says which).
void put_share(json& j, const char* key, double v) {
  if (v >= 0.0 && std::isfinite(v)) j[key] = v;
  if (std::isinf(v)) j["unbounded"] = key;
}
double read_share(const json& j, const char* key) {
  if (j.contains(key) && !j.at(key).is_null()) return j.at(key).get<double>();
  if (j.contains("unbounded") && j.at("unbounded") == key)
    return std::numeric_limits<double>::infinity();
  return -1.0;
}
}  // namespace

json plan_to_json(const calc::Plan& plan) {
  json j;
  j["summary"] = plan_summary(plan);
  j["quality"] = plan.quality;
  j["near_model"] = plan.near_model;
  j["near_model"]["name"] = nearfield::to_string(plan.near_model);
  j["near_switch"] = plan.near_switch;
  j["near_switch_reason"] = plan.near_switch_reason;
  j["direct_counts"] = plan.direct_counts;
  j["pairs_unreachable"] = plan.pairs_unreachable;
  j["near_far"] = plan.near_far;
  j["intensity_lookups"] = plan.intensity_lookups;
  const auto& d = plan.indirect_decision;
  j["indirect_decision"] = {{"run", d.run},
                            {"reason", d.reason},
                            {"observers_surface", d.observers_surface},
                            {"sampled", d.sampled},
                            {"mean_direct_lx", d.mean_direct_lx}};
  put_finite(j["indirect_decision"], "estimate_lx", d.estimate_lx);
  if (plan.indirect_run) {
    // The residual and worst_bounces of bounces that absorb nothing are infinite: left out.
    json run = *plan.indirect_run;
    for (auto it = run.begin(); it != run.end();)
      it = it->is_number_float() && !std::isfinite(it->get<double>()) ? run.erase(it) : ++it;
    j["indirect_run"] = std::move(run);
  }
  j["emergency_direct_only"] = plan.emergency_direct_only;
  j["refinements"] = plan.refinements;
  j["visibility"] = plan.visibility;
  j["scene_notes"] = plan.scene_notes;
  j["indirect_notes"] = plan.indirect_notes;
  j["indirect_warnings"] = plan.indirect_warnings;
  j["promise"] = plan.promise;
  j["direct_estimated"] = plan.direct_estimated;
  j["errors_estimated"] = plan.errors_estimated;
  json estimates = json::array();
  for (const auto& e : plan.estimates) {
    json one = {{"surface", e.surface}, {"probe_points", e.probe_points}};
    put_share(one, "direct", e.direct);
    put_share(one, "patch_size", e.patch_size);
    put_share(one, "patch_difference", e.patch_difference);
    put_share(one, "patch_order", e.patch_order);
    put_share(one, "bounces", e.bounces);
    put_finite(one, "total", e.total());
    estimates.push_back(std::move(one));
  }
  j["estimates"] = std::move(estimates);
  if (plan.daylight) j["daylight"] = *plan.daylight;  // the daylight scene only
  return j;
}

calc::Plan plan_from_json(const json& j) {
  calc::Plan plan;
  read_fields(j, "quality", plan.quality, "near_model", plan.near_model, "near_switch",
              plan.near_switch, "near_switch_reason", plan.near_switch_reason, "direct_counts",
              plan.direct_counts, "pairs_unreachable", plan.pairs_unreachable, "near_far",
              plan.near_far, "intensity_lookups", plan.intensity_lookups);
  const json& d = j.at("indirect_decision");
  read_fields(d, "run", plan.indirect_decision.run, "reason", plan.indirect_decision.reason,
              "observers_surface", plan.indirect_decision.observers_surface, "sampled",
              plan.indirect_decision.sampled);
  plan.indirect_decision.estimate_lx = read_maybe_infinite(d, "estimate_lx");
  d.at("mean_direct_lx").get_to(plan.indirect_decision.mean_direct_lx);
  if (j.contains("indirect_run") && !j.at("indirect_run").is_null()) {
    json run = j.at("indirect_run");
    // A number left out (or null, as older files wrote it) was infinite.
    const json defaults = calc::IndirectRunPlan{};
    for (const auto& [key, value] : defaults.items())
      if (value.is_number_float() && (!run.contains(key) || run.at(key).is_null()))
        run[key] = std::numeric_limits<double>::infinity();
    plan.indirect_run = run.get<calc::IndirectRunPlan>();
  }
  read_fields(j, "emergency_direct_only", plan.emergency_direct_only, "refinements",
              plan.refinements, "visibility", plan.visibility, "scene_notes", plan.scene_notes,
              "indirect_notes", plan.indirect_notes, "indirect_warnings", plan.indirect_warnings,
              "promise", plan.promise, "direct_estimated", plan.direct_estimated,
              "errors_estimated", plan.errors_estimated);
  for (const json& e : j.at("estimates")) {
    calc::SurfaceEstimate est;
    e.at("surface").get_to(est.surface);
    est.direct = read_share(e, "direct");
    est.patch_size = read_share(e, "patch_size");
    est.patch_difference = read_share(e, "patch_difference");
    est.patch_order = read_share(e, "patch_order");
    est.bounces = read_share(e, "bounces");
    e.at("probe_points").get_to(est.probe_points);
    plan.estimates.push_back(std::move(est));
  }
  if (j.contains("daylight")) plan.daylight = j.at("daylight").get<calc::DaylightPlan>();
  return plan;
}

}  // namespace luxgrid::report
