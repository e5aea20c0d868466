// Exact illuminance from a uniform (Lambertian) polygon: Lambert's formula, the "sum over edges
// of angle times cosine" (Baum et al. 1989), on the polygon clipped by the receiver's horizon.
#include <cmath>

#include "calc/nearfield/fan_sample.h"
#include "calc/nearfield/models.h"
#include "calc/nearfield/spherical.h"

namespace luxgrid::nearfield {

double lambert_uniform_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal,
                                   double luminance_cd_m2) {
  if (e.is_point()) return 0.0;
  if (!(glm::dot(point - e.centroid, e.normal) > 0.0)) return 0.0;  // only the emitting side
  const SmallPolygon poly = clip_to_horizon(e, point, normal);
  if (poly.n < 3) return 0.0;
  std::array<Vec3, kMaxPolygonVertices> u;
  for (int i = 0; i < poly.n; ++i) {
    const double d = glm::length(poly.v[i]);
    u[i] = d > 0.0 ? poly.v[i] / d : Vec3(0.0);
  }
  Vec3 sum{0.0};
  for (int i = 0; i < poly.n; ++i) sum += lambert_edge(u[i], u[(i + 1) % poly.n]);
  return sanitize_illuminance(luminance_cd_m2 * 0.5 * std::abs(glm::dot(normal, sum)));
}

}  // namespace luxgrid::nearfield
