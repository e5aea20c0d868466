// The plan's words come from its values (report/plan_text.h), and results.json's plan keeps those
// values: read back, they give the same words.
#include "report/plan_text.h"

#include <gtest/gtest.h>

#include "report/plan_json.h"

namespace luxgrid::report {
namespace {

calc::Plan sample_plan() {
  calc::Plan p;
  p.quality = calc::Quality::standard;
  p.near_switch = nearfield::NearFieldSwitch::automatic;
  p.direct_counts.near = 12;
  p.direct_counts.far = 30;
  p.direct_counts.point_sources = 2;
  calc::NearFarPlan nf;
  nf.group = {"mirel", 4, "luminaire 0"};
  nf.bound.outcome = nearfield::FarFieldBoundSummary::Outcome::no_point_in_reach;
  nf.bound.largest_dimension_m = 0.625;
  p.near_far.push_back(nf);
  calc::IntensityLookupPlan l;
  l.group = {"mirel", 1, "luminaire 7"};
  l.choice.kind = calc::IntensityLookupChoice::Kind::texture_within;
  l.choice.c_cells = 1440, l.choice.gamma_cells = 720;
  l.choice.deviation = 5.19e-5, l.choice.limit = 1e-3;
  p.intensity_lookups.push_back(l);
  p.visibility.on = true;
  p.visibility.obstacles = 2;
  p.visibility.non_convex_rooms = {"L office"};
  p.indirect_decision.reason = calc::indirect::IndirectReason::below_threshold;
  p.indirect_decision.estimate_lx = 1.5;
  p.indirect_decision.mean_direct_lx = 400.0;
  p.promise = 0.01;
  p.errors_estimated = true;
  calc::SurfaceEstimate e;
  e.surface = "workplane";
  e.direct = 0.02;
  p.estimates.push_back(e);
  return p;
}

TEST(PlanText, WordsEachDecisionFromItsValues) {
  const calc::Plan p = sample_plan();
  EXPECT_EQ(visibility_text(p),
            "on: 2 obstacles, non-convex room 'L office'; near-field pairs test visibility per "
            "quadrature node (soft shadows of area luminaires), far-field pairs from the centre "
            "of the opening");
  EXPECT_EQ(indirect_text(p),
            "skipped: integrating-sphere estimate 1.5 lx is below 1 % of the mean direct "
            "illuminance 400 lx");
  const std::string direct = direct_text(p);
  EXPECT_NE(direct.find(": 12 luminaire-point pairs near-field, 0 blended, 30 far-field, 2 from "
                        "point sources"),
            std::string::npos)
      << direct;
  EXPECT_NE(direct.find("; \"mirel\" (4 luminaires): no point of the scene in reach (D = 0.62 m)"),
            std::string::npos)
      << direct;
  EXPECT_NE(direct.find("\"mirel\" (luminaire 7): intensity texture 1440x720, within 0.00519 % "
                        "of the table (limit at standard: 0.1 %)"),
            std::string::npos)
      << direct;
  // 2 % direct against the promise of 1 %: a note and a warning naming the largest part.
  const auto notes = plan_notes(p);
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_EQ(notes[0],
            "estimated error at surface 'workplane': 2 % (direct 2 %) against the promise of 1 %");
  const auto warnings = plan_warnings(p);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0],
            "surface 'workplane': the plan's estimated error 2 % exceeds standard's promise of "
            "1 % (largest part: the far-field decision)");
  EXPECT_EQ(promise_text(calc::Quality::high),
            "high promises within 0.3 % of reference at every point brighter than 1 % of its "
            "surface's maximum");
}

// A local step (the whole mesh at half the size over the work limit, the mesh cut around the
// probes instead): a note saying what was cut and why, never a warning of its own, whatever the
// estimate; and results.json keeps its numbers.
TEST(PlanText, ALocalStepIsANoteWithWhatItCut) {
  calc::Plan p = sample_plan();
  p.estimates.front().patch_size = 0.02;  // above the promise: the estimate's own warning only
  calc::PatchRefinement r;
  r.outcome = calc::PatchRefinement::Outcome::local;
  r.from_m = 0.25, r.to_m = 0.125, r.estimate = 0.022, r.surface = "room wall 4";
  r.work_pairs = 2.5e7, r.work_limit_pairs = 1e7;
  r.local_points = 3, r.reach_m = 1.0, r.patches_cut = 340;
  p.refinements.push_back(r);
  EXPECT_EQ(plan_notes(p).front(),
            "indirect: patches cut to 0.125 m within 1 m of 3 probe points (340 patches of 0.25 m "
            "cut into quarters) where the difference asks for it: the patch-size difference at "
            "0.25 m (to the mesh at 0.5 m), 2.2 % on surface 'room wall 4', is above half of "
            "standard's promise, and a mesh at 0.125 m would cost 2.5e+07 pairs and links (a "
            "dense room's form-factor pairs, a pair counting 8 where rays are traced; a clustered "
            "room's links), above the limit of 1e+07");
  for (const std::string& w : plan_warnings(p))
    EXPECT_EQ(w.find("indirect:"), std::string::npos) << w;
  const nlohmann::json j = report::plan_to_json(p).at("refinements").at(0);
  EXPECT_EQ(j.at("outcome"), "local");
  EXPECT_EQ(j.at("patches_cut"), 340);
  const calc::PatchRefinement back =
      report::plan_from_json(report::plan_to_json(p)).refinements.at(0);
  EXPECT_EQ(back.outcome, calc::PatchRefinement::Outcome::local);
  EXPECT_EQ(back.local_points, 3u);
  EXPECT_EQ(back.reach_m, 1.0);
  EXPECT_EQ(back.patches_cut, 340u);
  // The other outcomes write none of the local step's keys (results.json as before).
  p.refinements.front().outcome = calc::PatchRefinement::Outcome::refined;
  EXPECT_FALSE(report::plan_to_json(p).at("refinements").at(0).contains("patches_cut"));
}

// A refinement the work limit stopped: a warning where the plan's estimate of the mesh that
// stayed exceeds the quality's target, a note where it does not (the refinement chooses on the
// difference d1 against half the target, the estimate extrapolates d1 with the measured order and
// adds the direct light's and the bounces').
TEST(PlanText, AStoppedRefinementWarnsOnlyWhereTheEstimateExceedsTheTarget) {
  calc::Plan p = sample_plan();
  p.estimates.front().direct = 0.001;
  p.estimates.front().patch_size = 0.0039;  // d1 0.8 % extrapolated with order 1.62
  p.estimates.front().bounces = 0.0;
  calc::PatchRefinement r;
  r.outcome = calc::PatchRefinement::Outcome::work_over_limit;
  r.from_m = 0.25, r.to_m = 0.125, r.estimate = 0.008, r.surface = "workplane";
  r.work_pairs = 2.6e7, r.work_limit_pairs = 1e7;
  p.refinements.push_back(r);
  const std::string stop =
      "indirect: the patch-size difference at 0.25 m (to the mesh at 0.5 m), 0.8 % on surface "
      "'workplane', is above half of standard's promise, but a mesh at 0.125 m would cost 2.6e+07 "
      "pairs and links (a dense room's form-factor pairs, a pair counting 8 where rays are "
      "traced; a clustered room's links), above the limit of 1e+07; the patch size stays 0.25 m";
  EXPECT_TRUE(plan_warnings(p).empty());
  const auto notes = plan_notes(p);
  ASSERT_FALSE(notes.empty());
  EXPECT_EQ(notes.front(), stop +
                               "; the plan's estimate there (the patch size's extrapolated with "
                               "the order measured on three meshes, with the direct light's and "
                               "the bounces') is at most 0.49 % on every surface, within "
                               "standard's promise");
  // Above the promise: the same words as a warning beside the estimate's own, no note.
  p.estimates.front().patch_size = 0.0095;
  const auto warnings = plan_warnings(p);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings.front(), stop);
  EXPECT_EQ(plan_notes(p).front().find("indirect:"), std::string::npos);
  // At reference the target is its convergence target, not a promise.
  p.quality = calc::Quality::reference;
  p.promise = 0.0;
  p.estimates.front().direct = 0.0;
  p.estimates.front().patch_size = 0.0019;
  r.outcome = calc::PatchRefinement::Outcome::refined;
  r.from_m = 0.2, r.to_m = 0.1, r.estimate = 0.0028;
  p.refinements = {r};
  EXPECT_EQ(plan_notes(p).front(),
            "indirect: patch size refined from 0.2 m to 0.1 m: the patch-size difference at 0.2 m "
            "(to the mesh at 0.4 m), 0.28 % on surface 'workplane', is above half of reference's "
            "convergence target of 0.2 %");
  // The yardstick's own estimate is set against its target, as the others' against a promise.
  EXPECT_EQ(plan_notes(p).at(1),
            "estimated error at surface 'workplane': 0.19 % (direct 0 %) against reference's "
            "convergence target of 0.2 %");
  // A reference the work limit stopped above its target warns: the yardstick is not converged.
  r.outcome = calc::PatchRefinement::Outcome::work_over_limit;
  r.to_m = 0.1, r.work_pairs = 9e7, r.work_limit_pairs = 5e7;
  p.refinements = {r};
  p.estimates.front().patch_size = 0.0021;
  ASSERT_EQ(plan_warnings(p).size(), 1u);
  EXPECT_NE(plan_warnings(p).front().find("reference's convergence target of 0.2 %, but a mesh "
                                          "at 0.1 m would cost 9e+07"),
            std::string::npos);
  p.estimates.front().patch_size = 0.0019;
  EXPECT_TRUE(plan_warnings(p).empty());
  // Estimates not made: the stop stays a warning.
  p.errors_estimated = false;
  EXPECT_EQ(plan_warnings(p).size(), 1u);
}

// One mesh solved (draft): the words say the patch size is not estimated instead of quoting 0 %.
TEST(PlanText, APatchSizeNotEstimatedIsSaid) {
  calc::Plan p = sample_plan();
  p.quality = calc::Quality::draft;
  p.promise = 0.0;
  calc::IndirectRunPlan run;
  run.bounces_asked = 1, run.bounces_run = 1, run.patches = 108, run.patch_size_m = 1.0;
  run.estimated = true, run.worst_bounces = 0.62;
  p.indirect_run = run;
  p.estimates.front().bounces = 0.62;
  const std::string text = indirect_text(p);
  EXPECT_NE(text.find("; estimated error: patch size not estimated (one mesh solved), bounces not "
                      "followed up to 62 % of E"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("extrapolated"), std::string::npos) << text;
  EXPECT_EQ(plan_notes(p).front(),
            "estimated error at surface 'workplane': 64 % (direct 2 %, patch size not estimated "
            "(one mesh solved), bounces 62 %)");
}

TEST(PlanText, WordsTheSolversNotes) {
  using calc::indirect::IndirectNote;
  IndirectNote budget;
  budget.kind = IndirectNote::Kind::budget_above_limit;
  budget.asked = 20000, budget.limit = 10000, budget.matrix_mb = 400;
  EXPECT_EQ(indirect_note_text(budget),
            "indirect: the budget of 20000 patches per room is above the limit of 10000 (a "
            "form-factor matrix of 400 MB); 10000 used");
  IndirectNote rooms;
  rooms.kind = IndirectNote::Kind::rooms_raised;
  rooms.rooms = 60, rooms.from_m = 0.5, rooms.to_m = 0.5477, rooms.limit = 100000;
  EXPECT_EQ(indirect_note_text(rooms),
            "all 60 rooms: patch size raised from 0.5 m to 0.548 m to stay within 100000 patches "
            "in all rooms");
  IndirectNote outside;
  outside.kind = IndirectNote::Kind::opening_outside;
  outside.luminaire = "luminaire 1";
  outside.fraction = 0.9984, outside.length_m = 100, outside.width_m = 100;
  outside.entering_lm = 16, outside.flux_lm = 10000;
  outside.rooms_entered = {"box", "annex"};
  EXPECT_EQ(indirect_note_text(outside),
            "luminaire 1: 99.84 % of its luminous opening (rectangle 100 x 100 m) lies outside "
            "its room or inside an obstacle; that light does not enter the room: 16 lm of 10000 "
            "lm enter room 'box', 'annex'");
  // The plan lists the solver's notes after the scene's, its warnings before the estimates'.
  calc::Plan p;
  calc::SceneNote left_out;
  left_out.kind = calc::SceneNote::Kind::observers_left_out;
  left_out.observers = 1;
  p.scene_notes = {left_out};
  p.indirect_notes = {rooms};
  p.indirect_warnings = {budget};
  EXPECT_EQ(plan_notes(p),
            (std::vector<std::string>{scene_note_text(left_out), indirect_note_text(rooms)}));
  EXPECT_EQ(plan_warnings(p), std::vector<std::string>{indirect_note_text(budget)});
}

TEST(PlanText, SceneNotesInWords) {
  // The emergency scene's choices, each output as the project gave it; past the third listed
  // output an ellipsis.
  calc::SceneNote scene;
  scene.luminaires = 4, scene.of_luminaires = 5;
  scene.outputs = {{"a", 0.05, 0.0, ""}, {"c", 1.0, 0.0, "lam"}, {"d", 0.31, 100.0, ""}};
  EXPECT_EQ(scene_note_text(scene),
            "emergency scene (EN 1838): direct light only, from the 4 of 5 luminaires with an "
            "emergency entry, at their emergency output (a: 0.05 of its output; c: photometry "
            "\"lam\"; d: 100 lm; ...)");
  scene.luminaires = 3;
  EXPECT_EQ(scene_note_text(scene),
            "emergency scene (EN 1838): direct light only, from the 3 of 5 luminaires with an "
            "emergency entry, at their emergency output (a: 0.05 of its output; c: photometry "
            "\"lam\"; d: 100 lm)");
  calc::SceneNote left_out;
  left_out.kind = calc::SceneNote::Kind::observers_left_out;
  left_out.observers = 2;
  EXPECT_EQ(scene_note_text(left_out),
            "emergency scene: 2 observers surface(s) left out (UGR is not an emergency lighting "
            "quantity)");
}

// A room whose reflectances absorb nothing: the residual and the bounces' share are infinite.
// results.json holds no null (docs/reliability.md): they are left out, read back as infinity,
// and the warning says "unbounded" instead of "inf %".
TEST(PlanText, InfiniteEstimatesAreLeftOutAndReadBack) {
  calc::Plan p = sample_plan();
  p.promise = 0.01;
  p.errors_estimated = true;
  calc::IndirectRunPlan run;
  run.bounces_asked = 0, run.bounces_run = 1000, run.patches = 64, run.patch_size_m = 0.5;
  run.residual = std::numeric_limits<double>::infinity();
  run.worst_bounces = std::numeric_limits<double>::infinity();
  p.indirect_run = run;
  calc::SurfaceEstimate e;
  e.surface = "wp", e.direct = 0.0, e.patch_size = 0.002;
  e.bounces = std::numeric_limits<double>::infinity();
  p.estimates = {e};
  calc::SurfaceEstimate unlit;
  unlit.surface = "probes", unlit.direct = 0.001;  // patch_size, bounces: -1, not estimated
  p.estimates.push_back(unlit);
  // draft takes a texture without a limit (calc::texture_limit is +infinity).
  calc::IntensityLookupPlan draft_lookup;
  draft_lookup.group = {"mirel", 25, ""};
  draft_lookup.choice.kind = calc::IntensityLookupChoice::Kind::texture_draft;
  draft_lookup.choice.quality = calc::Quality::draft;
  draft_lookup.choice.limit = calc::texture_limit(calc::Quality::draft);
  p.intensity_lookups = {draft_lookup};
  const nlohmann::json j = plan_to_json(p);
  EXPECT_EQ(j.dump().find("null"), std::string::npos) << j.dump();
  EXPECT_FALSE(j.at("intensity_lookups").at(0).at("choice").contains("limit"));
  EXPECT_FALSE(j.at("indirect_run").contains("residual"));
  EXPECT_FALSE(j.at("estimates").at(0).contains("total"));
  EXPECT_EQ(j.at("estimates").at(0).at("unbounded"), "bounces");
  EXPECT_FALSE(j.at("estimates").at(1).contains("patch_size"));
  const calc::Plan back = plan_from_json(nlohmann::json::parse(j.dump(1)));
  EXPECT_EQ(back.indirect_run->residual, std::numeric_limits<double>::infinity());
  EXPECT_EQ(back.estimates.at(0).bounces, std::numeric_limits<double>::infinity());
  EXPECT_EQ(back.estimates.at(1).patch_size, -1.0);
  EXPECT_EQ(back.intensity_lookups.at(0).choice.limit, std::numeric_limits<double>::infinity());
  EXPECT_EQ(plan_to_json(back), j);
  EXPECT_EQ(plan_warnings(back), plan_warnings(p));
  bool unbounded = false;
  for (const auto& w : plan_warnings(p)) {
    EXPECT_EQ(w.find("inf %"), std::string::npos) << w;
    unbounded = unbounded || w.find("estimated error is unbounded") != std::string::npos;
  }
  EXPECT_TRUE(unbounded);
}

TEST(PlanText, ResultsJsonKeepsTheValuesTheWordsComeFrom) {
  calc::Plan p = sample_plan();
  calc::IndirectRunPlan run;
  run.bounces_asked = 0, run.bounces_run = 7, run.patches = 1728, run.patch_size_m = 0.25;
  run.estimated = true, run.worst_patch_size = 0.004;
  p.indirect_run = run;
  p.indirect_decision.estimate_lx = std::numeric_limits<double>::infinity();
  calc::PatchRefinement r;
  r.outcome = calc::PatchRefinement::Outcome::work_over_limit;
  r.from_m = 0.5, r.to_m = 0.25, r.estimate = 0.008, r.surface = "floor";
  r.work_pairs = 7.5e7, r.work_limit_pairs = 1e7;
  p.refinements.push_back(r);
  calc::indirect::IndirectNote raised;
  raised.kind = calc::indirect::IndirectNote::Kind::room_raised_meshed;
  raised.room = "hall", raised.from_m = 0.5, raised.to_m = 0.71, raised.budget = 4000;
  p.indirect_notes.push_back(raised);
  calc::SceneNote scene;
  scene.luminaires = 2, scene.of_luminaires = 3;
  scene.outputs = {{"a", 0.05, 0.0, ""}, {"b", 0.25, 250.0, ""}};
  p.scene_notes.push_back(scene);
  const nlohmann::json j = plan_to_json(p);
  EXPECT_EQ(j.at("summary"), plan_summary(p));
  // Through text, as results.json holds it.
  const calc::Plan back = plan_from_json(nlohmann::json::parse(j.dump(1)));
  EXPECT_EQ(direct_text(back), direct_text(p));
  EXPECT_EQ(indirect_text(back), indirect_text(p));
  EXPECT_EQ(visibility_text(back), visibility_text(p));
  EXPECT_EQ(plan_notes(back), plan_notes(p));
  EXPECT_EQ(plan_warnings(back), plan_warnings(p));
  EXPECT_EQ(back.indirect_decision.estimate_lx, std::numeric_limits<double>::infinity());
  EXPECT_EQ(plan_to_json(back), j);
  // A plan without one of its keys is refused.
  nlohmann::json missing = j;
  missing.erase("near_far");
  EXPECT_THROW(plan_from_json(missing), nlohmann::json::exception);
}

}  // namespace
}  // namespace luxgrid::report
