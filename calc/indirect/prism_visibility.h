#pragma once
// Visibility inside a room that is an extruded outline (a prism), until geometry/'s AABB tree
// lands: a segment between two points of the prism stays inside iff its floor-plan shadow does
// not cross the outline (floor and ceiling are parallel planes, so the z-range cannot be left).
// Exact for L-shapes and every other simple outline; no obstacles.
#include "calc/indirect/form_factor.h"
#include "calc/scene.h"

namespace luxgrid::calc::indirect {

// Occlusion callback for the walls of `room` (true = blocked). The room is copied in.
OcclusionFn prism_occlusion(const Room& room);

}  // namespace luxgrid::calc::indirect
