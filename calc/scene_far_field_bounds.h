#pragma once
// The near/far decision of a run (docs/nearfield.md): one error-bound map (nearfield/
// far_field_bound.h) per distinct emitter of the scene, attached to every copy, and the plan's
// summary of each.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "calc/direct_reach.h"
#include "calc/nearfield/emitter.h"
#include "calc/plan.h"
#include "calc/scene.h"

namespace luxgrid::calc {

// When the plan switches automatically, builds the map once per distinct emitter (same
// distribution object and the same opening polygon in the luminaire frame: copies, arrays and
// luminaires sharing a file without TILT) and attaches it to `emitters` (parallel to
// scene.luminaires). Returns each distinct emitter's map summary for the plan.
//
// With `reach` (and the zone of every point of every surface, `zones[surface][point]`), each map
// measures only what the run's pairs will ask of it: the directions its luminaires see the
// scene's active points in, each out to the farthest of them (nearfield::MapDemand), when those
// pairs are at most kMapDemandPairs; beyond, the whole map.
std::vector<NearFarPlan> attach_far_field_bounds(
    const Scene& scene, const Plan& plan, std::vector<nearfield::Emitter>& emitters,
    const DirectReach* reach = nullptr, const std::vector<std::vector<uint32_t>>* zones = nullptr);

// Marking a pair's direction costs about a tenth of a microsecond; the whole map of one emitter
// costs 0.05 to 0.5 s of processor time. Above this many pairs per distinct emitter the marking
// would cost about as much as the map it saves.
inline constexpr std::size_t kMapDemandPairs = 2'000'000;

}  // namespace luxgrid::calc
