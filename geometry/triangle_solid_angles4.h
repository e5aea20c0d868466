#pragma once
// The solid angles of four planar triangles seen from one point, at once (SIMD lanes): the same
// values as triangle_solid_angle_from (geometry/spherical.h) to the bit. The first bounce's
// integration pieces come four at a time (a patch's fan of four triangles, a triangle's four
// halves), and each solid angle alone is a chain of square roots, a division and a table angle
// that waits on itself.
#include "util/robust_math.h"
#include "util/simd.h"

namespace luxgrid::geometry {

// out[k] = triangle_solid_angle_from(s, a[k], b[k], c[k]): the same template of
// geometry/spherical.h over four lanes. One version per target (util/simd.h's
// LUXGRID_MULTIVERSION): triangle_solid_angles_from4_avx2, _default, and the processor's.
LUXGRID_MULTIVERSION_DECLARE(void, triangle_solid_angles_from4,
                             (const Vec3& s, const Vec3 (&a)[4], const Vec3 (&b)[4],
                              const Vec3 (&c)[4], double (&out)[4]))

}  // namespace luxgrid::geometry
