#include <cmath>

#include "calc/nearfield/fan_sample.h"
#include "calc/nearfield/models.h"
#include "calc/nearfield/receiver_kernel.h"

namespace luxgrid::nearfield {

// Inverse-square law with the cosine of incidence ([Luksch2020, Sec. 2.1], the far-field model).
// The receiver's weight (receiver_kernel.h) replaces the cosine for cylindrical and
// semi-cylindrical illuminance: E = I(-w) g(w) / d^2.
double point_source_illuminance(const photometry::IntensityDistribution& distribution,
                                const glm::dmat3& world_to_local, const Vec3& source,
                                const Vec3& point, const Receiver& receiver) {
  return point_source_illuminance_with(
      [&](const Vec3& local, double inv_length) {
        return distribution.intensity(local * inv_length);
      },
      world_to_local, source, point, receiver);
}

// The whole luminaire as a point at the centroid of its opening, looked up in the emitter's
// far-field lookup (the texture where calc/intensity_lookup.h chose it).
double far_field_illuminance(const Emitter& e, const Vec3& point, const Receiver& receiver) {
  return point_source_illuminance(e.far_lookup(), e.world_to_local, e.centroid, point, receiver);
}

double far_field_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal) {
  return far_field_illuminance(e, point, Receiver::planar(normal));
}

}  // namespace luxgrid::nearfield
