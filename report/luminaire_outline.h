#pragma once
// The luminous opening of a placed luminaire as a world polygon, so the plan view and the maps
// draw a 2 m slot as 2 m long and a 0.6 m panel as 0.6 m square, turned as the luminaire is.
#include <vector>

#include "calc/scene.h"

namespace luxgrid::report {

// The opening's corners in world coordinates (a disk as a 32-gon); empty for a point source.
std::vector<Vec3> luminous_outline(const calc::Luminaire& l);

}  // namespace luxgrid::report
