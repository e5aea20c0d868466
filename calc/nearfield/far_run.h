#pragma once
// The far-field pairs of one receiver point on a plane, a run of emitters at once: calc/direct
// takes the far field alone for most pairs of a large room (142 million of the 200 x 100 m hall's
// 176 million at standard), and one pair at a time each waited on its intensity look-up's angles.
// The pairs' geometry first, then the look-ups of each run of emitters that share a far-field
// lookup at once (IntensityDistribution::intensities: a table's angles as lanes), then each pair's
// illuminance: point_source_illuminance's two steps (models.h: far_pair, far_pair_illuminance)
// on the same values, so the same bits as far_field_illuminance pair by pair.
#include <cstddef>

#include "calc/nearfield/emitter.h"

namespace luxgrid::nearfield {

// out[k] = far_field_illuminance(*emitters[k], point, Receiver::planar(normal)) for k < count.
void far_field_pairs(const Emitter* const* emitters, std::size_t count, const Vec3& point,
                     const Vec3& normal, double* out);

}  // namespace luxgrid::nearfield
