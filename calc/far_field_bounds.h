#pragma once
// The near/far decision of a run (docs/nearfield.md): one error-bound map (nearfield/
// far_field_bound.h) per distinct emitter of the scene, attached to every copy, and the plan's
// line for each.
#include <string>
#include <vector>

#include "calc/nearfield/emitter.h"
#include "calc/plan.h"
#include "calc/scene.h"

namespace luxgrid::calc {

// When the plan switches automatically, builds the map once per distinct emitter (same
// distribution object and the same opening polygon in the luminaire frame: copies, arrays and
// luminaires sharing a file without TILT) and attaches it to `emitters` (parallel to
// scene.luminaires). Returns one line per distinct emitter for the plan.
std::vector<std::string> attach_far_field_bounds(const Scene& scene, const Plan& plan,
                                                 std::vector<nearfield::Emitter>& emitters);

}  // namespace luxgrid::calc
