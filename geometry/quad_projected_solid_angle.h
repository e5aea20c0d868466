#pragma once
// Lambert's projected solid angle of a quadrilateral, its four edges at once (SIMD lanes): the
// same value as projected_solid_angle (geometry/spherical.h) to the bit. Reflected light's
// gather takes it for nearly every exact form factor (a patch or a cell wholly above the
// receiver's horizon is a parallelogram), where the edges one by one, each a chain of square
// roots, divisions and a table angle waiting for the one before, were a tenth of a whole office
// calculation.
#include "util/robust_math.h"
#include "util/simd.h"

namespace luxgrid::geometry {

// projected_solid_angle(rel, 4, n): the corners rel[0..4) relative to the viewpoint, the unit
// normal n. Each lane computes what lambert_edge computes for its edge (the same templates of
// geometry/spherical.h, over four lanes), and the edges are added in the same order; a
// quadrilateral whose corners or edges need the scalar code's other branches (a corner at the
// viewpoint, an angle for std::atan2) takes that code. One version per target (util/simd.h's
// LUXGRID_MULTIVERSION): quad_projected_solid_angle_avx2, _default, and the processor's.
LUXGRID_MULTIVERSION_DECLARE(double, quad_projected_solid_angle, (const Vec3* rel, const Vec3& n))

}  // namespace luxgrid::geometry
