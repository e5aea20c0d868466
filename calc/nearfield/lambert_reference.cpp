// Exact illuminance from a uniform (Lambertian) polygon: L times the projected solid angle of the
// polygon clipped by the receiver's horizon (Lambert's formula [Baum1989, Eq. 2],
// geometry/spherical.h).
#include <cmath>

#include "calc/nearfield/fan_sample.h"
#include "calc/nearfield/models.h"
#include "geometry/spherical.h"

namespace luxgrid::nearfield {

double lambert_uniform_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal,
                                   double luminance_cd_m2) {
  if (e.is_point()) return 0.0;
  if (!(glm::dot(point - e.centroid, e.normal) > 0.0)) return 0.0;  // only the emitting side
  const OpeningPolygon poly = clip_to_horizon(e, point, normal);
  return sanitize_illuminance(luminance_cd_m2 *
                              geometry::projected_solid_angle(poly.v.data(), poly.n, normal));
}

}  // namespace luxgrid::nearfield
