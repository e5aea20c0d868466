#include <cmath>

#include "calc/nearfield/fan_sample.h"
#include "calc/nearfield/models.h"
#include "calc/nearfield/receiver_kernel.h"

namespace luxgrid::nearfield {

// Inverse-square law with the cosine of incidence ([Luksch2020, Sec. 2.1], the far-field model): the whole
// luminaire as a point at the centroid of its opening. A receiver at the centroid itself gets 0
// (the point model has no answer there; the near-field models do).
// The receiver's weight (receiver_kernel.h) replaces the cosine for cylindrical and
// semi-cylindrical illuminance: E = I(-w) g(w) / d^2.
double far_field_illuminance(const Emitter& e, const Vec3& point, const Receiver& receiver) {
  const Vec3 r = e.centroid - point;
  const double d2 = glm::dot(r, r);
  if (!(d2 > 0.0)) return 0.0;
  const Vec3 w = r / std::sqrt(d2);
  const double weight = receiver_weight(receiver, w);
  if (!(weight > 0.0)) return 0.0;
  return sanitize_illuminance(e.intensity_towards(-w) * weight / d2);
}

double far_field_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal) {
  return far_field_illuminance(e, point, Receiver::planar(normal));
}

}  // namespace luxgrid::nearfield
