#pragma once
// The near/far switch's weights (illuminance.h, switch_weights) of one receiver point and a run
// of emitters at once. Per pair the switch needs the direction's photometric angles to find it in
// the emitter's error-bound map (far_field_bound.h): in a large hall, where a coarse table keeps
// some direction near field at every distance, that is every pair (176 million on the 200 x 100 m
// hall at standard), and one pair at a time the angles were a chain of dependent operations
// waiting on each other (an eighth of the hall's CPU). Four pairs' angles are computed as the
// lanes of one computation (photometry::table_angles_of), the rest per pair as before: the same
// weights to the bit.
#include <cstddef>

#include "calc/nearfield/illuminance.h"
#include "util/simd.h"

namespace luxgrid::nearfield {

// out[k] = switch_weights(*emitters[k], point) for k < count, the same bits (an AVX2 version
// where the processor has it, the baseline's otherwise; both the same bits).
LUXGRID_MULTIVERSION_DECLARE(void, switch_weights_run,
                             (const Emitter* const* emitters, size_t count, const Vec3& point,
                              SwitchWeights* out))

}  // namespace luxgrid::nearfield
