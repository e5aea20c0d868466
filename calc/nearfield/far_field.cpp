#include <cmath>

#include "calc/nearfield/fan_sample.h"
#include "calc/nearfield/models.h"

namespace luxgrid::nearfield {

// Inverse-square law with the cosine of incidence (ARCHITECTURE.md, model 1): the whole
// luminaire as a point at the centroid of its opening. A receiver at the centroid itself gets 0
// (the point model has no answer there; the near-field models do).
double far_field_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal) {
  const Vec3 r = e.centroid - point;
  const double d2 = glm::dot(r, r);
  if (!(d2 > 0.0)) return 0.0;
  const Vec3 w = r / std::sqrt(d2);
  const double cos_x = glm::dot(w, normal);
  if (!(cos_x > 0.0)) return 0.0;
  return sanitize_illuminance(e.intensity_towards(-w) * cos_x / d2);
}

}  // namespace luxgrid::nearfield
