#include "calc/nearfield/switch_run.h"

#include "calc/nearfield/far_field_bound.h"

namespace luxgrid::nearfield {
namespace {

// Four pairs as lanes: the unit direction in each emitter's frame as switch_weights computes it
// (r = point - centroid, d = |r| as glm::length, world_to_local * (r / d) in glm's order of
// operations), then its angles; each lane's weights from its angles by the emitter's own map. A
// lane whose angles the table does not give (the vertical, d = 0), or whose emitter has no map,
// takes switch_weights itself.
template <class T>
LUXGRID_LANE void switch_lanes(const Emitter* const* emitters, const Vec3& point,
                               SwitchWeights* out) {
  // Lane l's emitter's centroid and rotation (lambdas that return doubles: one returning lanes
  // would be a call across targets, util/simd.h).
  const T rx = point.x - simd::make<T>([&](int l) { return emitters[l]->centroid.x; });
  const T ry = point.y - simd::make<T>([&](int l) { return emitters[l]->centroid.y; });
  const T rz = point.z - simd::make<T>([&](int l) { return emitters[l]->centroid.z; });
  const T d = simd::sqrt(rx * rx + ry * ry + rz * rz);
  const T vx = rx / d, vy = ry / d, vz = rz / d;
  T m[3][3];
  for (int col = 0; col < 3; ++col)
    for (int row = 0; row < 3; ++row)
      m[col][row] = simd::make<T>([&](int l) { return emitters[l]->world_to_local[col][row]; });
  const T ux = m[0][0] * vx + m[1][0] * vy + m[2][0] * vz;
  const T uy = m[0][1] * vx + m[1][1] * vy + m[2][1] * vz;
  const T uz = m[0][2] * vx + m[1][2] * vy + m[2][2] * vz;
  T c, gamma;
  const simd::Mask<T> ok = photometry::table_angles_of(ux, uy, uz, c, gamma);
  for (int l = 0; l < simd::kLanes; ++l) {
    const Emitter& e = *emitters[l];
    if (ok[l] && e.far_bound && e.largest_dimension_m > 0.0 && d[l] > 0.0)
      out[l] = switch_weights_of_bound(e, e.far_bound->weights({c[l], gamma[l]}, d[l]), d[l]);
    else
      out[l] = switch_weights(e, point);
  }
}

LUXGRID_LANE void switch_run_kernel(const Emitter* const* emitters, size_t count, const Vec3& point,
                                    SwitchWeights* out) {
  size_t k = 0;
  for (; k + simd::kLanes <= count; k += simd::kLanes)
    switch_lanes<simd::D4>(emitters + k, point, out + k);
  for (; k < count; ++k) out[k] = switch_weights(*emitters[k], point);
}

}  // namespace

LUXGRID_MULTIVERSION(void, switch_weights_run,
                     (const Emitter* const* emitters, size_t count, const Vec3& point,
                      SwitchWeights* out),
                     (emitters, count, point, out), switch_run_kernel)

}  // namespace luxgrid::nearfield
