#pragma once
// Which samples of the near/far map (far_field_bound.h) measure the same thing: the map is
// measured once per class and copied to the rest (docs/nearfield.md, "Mirror images measured
// once").
#include <vector>

#include "calc/nearfield/emitter.h"

namespace luxgrid::nearfield {

// For every sample of the map's direction grid (gamma row-major, kCSamples per row), the
// sample that measures for it (itself, or the smallest index of its class):
// - the samples of a pole row (gamma 0 or 180 degrees) are one direction: the row's first;
// - where the emitter is its own mirror image across the plane C 0-180 (C -> -C) or C 90-270
//   (C -> 180 - C), a sample and its mirror image. Both the opening and the fixed rule's nodes
//   mirror onto themselves (to 1e-9 of the opening's size), and the table's C planes and their
//   candela values mirror onto planes of the same values, exactly (the expanded copies of a
//   symmetric file's half or quarter). Only when `near_is_table`: the near values are then the
//   table rung's, an integral exact to rounding, so a direction and its mirror image measure
//   the same; a cubature's nodes need not mirror onto themselves.
std::vector<int> map_sample_representatives(const Emitter& e, bool near_is_table);

}  // namespace luxgrid::nearfield
