#include "calc/indirect/form_factor.h"

#include <algorithm>
#include <array>
#include <vector>

#include "geometry/quad_projected_solid_angle.h"
#include "geometry/spherical.h"

namespace luxgrid::calc::indirect {

double point_polygon_form_factor(const Vec3& x, const Vec3& n, const Polygon3& polygon) {
  return point_polygon_form_factor(x, n, polygon.data(), static_cast<int>(polygon.size()));
}

double point_polygon_form_factor(const Vec3& x, const Vec3& n, const Vec3* corners, int m) {
  // The horizon clip into a stack buffer: this runs for every near patch (and cell) of every
  // receiver, so no heap allocation. A polygon of m corners clips to at most 2 m.
  constexpr int kMaxStack = 16;
  if (m < 3) return 0.0;
  double psa = 0.0;
  if (m > kMaxStack) {
    const Polygon3 clipped = geometry::clip_to_half_space(Polygon3(corners, corners + m), x, n);
    std::vector<Vec3> rel(clipped.size());
    for (size_t k = 0; k < clipped.size(); ++k) rel[k] = clipped[k] - x;
    psa = geometry::projected_solid_angle(rel.data(), rel.size(), n);
  } else {
    // Most near patches lie wholly above the horizon, where the clip changes nothing; nearly
    // all of them are parallelograms, whose four edges are taken at once.
    std::array<Vec3, kMaxStack> rel;
    if (geometry::relative_if_wholly_above(corners, m, x, n, rel)) {
      psa = m == 4 ? geometry::quad_projected_solid_angle(rel.data(), n)
                   : geometry::projected_solid_angle(rel.data(), static_cast<size_t>(m), n);
    } else {
      const auto clipped = geometry::clip_to_half_space_relative<2 * kMaxStack>(corners, m, x, n);
      psa = clipped.n == 4 ? geometry::quad_projected_solid_angle(clipped.v.data(), n)
                           : geometry::projected_solid_angle(clipped.v.data(),
                                                             static_cast<size_t>(clipped.n), n);
    }
  }
  return std::clamp(psa / kPi, 0.0, 1.0);
}

double point_kernel_form_factor(const Vec3& x, const Vec3& n, const Vec3& c, const Vec3& m,
                                double area_m2) {
  const Vec3 d = x - c;
  const double d2 = glm::dot(d, d);
  if (!(d2 > 0.0)) return 0.0;
  const double h_source_m = std::max(0.0, glm::dot(m, d));
  const double h_receiver_m = std::max(0.0, -glm::dot(n, d));
  return area_m2 * point_kernel_pi_per_m2(h_source_m, h_receiver_m, d2) / kPi;
}

double quarter_kernel_form_factor(const Vec3& x, const Vec3& n, const Polygon3& polygon,
                                  const Vec3& centroid, const std::array<Vec3, 4>& quarter,
                                  const Vec3& m, double area_m2, double diameter_m, double min_d2) {
  // Every vertex in front of the receiver: at once when the circumscribed sphere is (a
  // parallelogram's vertices are at most half its diameter from its centroid), else one by one.
  if (!(glm::dot(n, centroid - x) > 0.5 * diameter_m))
    for (const Vec3& v : polygon)
      if (!(glm::dot(n, v - x) > 0.0)) return -1.0;
  double sum = 0.0;
  for (const Vec3& c : quarter) {
    const Vec3 d = x - c;
    const double d2 = glm::dot(d, d);
    if (!(d2 > min_d2)) return -1.0;
    sum +=
        point_kernel_pi_per_m2(std::max(0.0, glm::dot(m, d)), std::max(0.0, -glm::dot(n, d)), d2);
  }
  const double f4 = 0.25 * area_m2 * sum / kPi;
  const double f1 = point_kernel_form_factor(x, n, centroid, m, area_m2);
  const double f = (4.0 * f4 - f1) / 3.0;
  return f >= 0.0 ? f : -1.0;
}

}  // namespace luxgrid::calc::indirect
