#include "geometry/triangle_solid_angles4.h"

#include "geometry/spherical.h"
#include "util/simd.h"

namespace luxgrid::geometry {

namespace {

// triangle_solid_angle_from over four lanes, one triangle each.
LUXGRID_LANE void triangles_kernel(const Vec3& s, const Vec3 (&a)[4], const Vec3 (&b)[4],
                                   const Vec3 (&c)[4], double (&out)[4]) {
  using simd::D4;
  const simd::V3<D4> sl = v3_lanes([&s](int) { return s; });
  const D4 omega = triangle_solid_angle_from(sl, v3_lanes([&a](int l) { return a[l]; }),
                                             v3_lanes([&b](int l) { return b[l]; }),
                                             v3_lanes([&c](int l) { return c[l]; }));
  simd::store(omega, out);
}

}  // namespace

LUXGRID_MULTIVERSION(void, triangle_solid_angles_from4,
                     (const Vec3& s, const Vec3 (&a)[4], const Vec3 (&b)[4], const Vec3 (&c)[4],
                      double (&out)[4]),
                     (s, a, b, c, out), triangles_kernel)

}  // namespace luxgrid::geometry
