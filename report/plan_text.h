#pragma once
// The plan in words (calc/plan.h holds it as values): the sentences report.html's appendix, the
// terminal's warnings, `luxgrid cost` and results.json's short `summary` show. Each function
// words one decision from its code and numbers; nothing here decides anything.
#include <string>
#include <vector>

#include "calc/plan.h"

namespace luxgrid::report {

// What the quality promises: "standard promises within 1 % of reference at every point brighter
// than 1 % of its surface's maximum".
std::string promise_text(calc::Quality quality);

// One distinct emitter's near/far map: "smooth distribution (geometry of the opening): near
// field out to 7.2 D (...), 2.0 D at least, median 3.4 D (D = 0.62 m); far field within 1 %
// beyond (measured at most 0.8 %); the fixed rule within ...".
std::string far_field_bound_text(const nearfield::FarFieldBoundSummary& bound);

// What one distribution's far-field pairs look up: "intensity texture 1440x720, within 0.0052 %
// of the table (limit at standard: 0.1 %)".
std::string intensity_lookup_text(const calc::IntensityLookupChoice& choice);

// What reflected light's solver noted: "room 'hall': patch size raised from 0.5 m to 0.71 m to
// stay within 4000 patches per room".
std::string indirect_note_text(const calc::indirect::IndirectNote& note);

// What was done to the scene: "emergency scene (EN 1838): direct light only, from the 3 of 4
// luminaires with an emergency entry, at their emergency output (a: 0.05 of its output; ...)".
std::string scene_note_text(const calc::SceneNote& note);

// Whether reflected light runs and why: "skipped: all reflectances are 0".
std::string indirect_decision_text(const calc::indirect::IndirectDecision& decision);

// The plan's three sentences: direct light (models, pair counts, per emitter its map, per
// distribution its lookup), reflected light (the decision, or what the run did and its estimated
// error) and visibility.
std::string direct_text(const calc::Plan& plan);
std::string indirect_text(const calc::Plan& plan);
std::string visibility_text(const calc::Plan& plan);

// The plan's notes in order: the quality's switch, the scene's notes, the patch-size refinements,
// the solver's notes, the estimated error per surface and the textures' note.
std::vector<std::string> plan_notes(const calc::Plan& plan);
// The plan's warnings in order: refinements that stopped, the solver's, then per surface an
// estimate that is missing or above the promise.
std::vector<std::string> plan_warnings(const calc::Plan& plan);

// One short line for results.json's `plan.summary`: "direct: hybrid by an error bound, 1200
// pairs near-field of 4800; indirect: converged interreflection, 1728 patches; visibility: off;
// estimated error up to 0.41 % (promise 1 %)".
std::string plan_summary(const calc::Plan& plan);

}  // namespace luxgrid::report
