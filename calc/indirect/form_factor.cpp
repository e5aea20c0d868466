#include "calc/indirect/form_factor.h"

#include "calc/nearfield/spherical.h"

namespace luxgrid::calc::indirect {

namespace {
// Vertices closer than this to the receiver point are dropped from Lambert's sum: their edges
// subtend no defined angle and (being in the receiver's tangent plane after the horizon clip)
// contribute nothing to the cosine-weighted integral.
constexpr double kMinVertexDistance_m = 1e-12;
}  // namespace

double point_polygon_form_factor(const Vec3& x, const Vec3& n, const Polygon3& polygon) {
  const Polygon3 clipped = clip_to_half_space(polygon, x, n);
  if (clipped.size() < 3) return 0.0;
  Vec3 sum(0.0);
  Vec3 prev(0.0);
  bool have_prev = false;
  Vec3 first(0.0);
  for (const auto& v : clipped) {
    const Vec3 r = v - x;
    const double len = glm::length(r);
    if (!(len > kMinVertexDistance_m)) continue;
    const Vec3 u = r / len;
    if (have_prev) sum += nearfield::lambert_edge(prev, u);
    else first = u;
    prev = u;
    have_prev = true;
  }
  if (!have_prev) return 0.0;
  sum += nearfield::lambert_edge(prev, first);
  const double f = std::abs(glm::dot(n, sum)) / (2.0 * kPi);
  return std::clamp(f, 0.0, 1.0);
}

double point_kernel_form_factor(const Vec3& x, const Vec3& n, const Vec3& c, const Vec3& m,
                                double area_m2) {
  const Vec3 d = x - c;
  const double d2 = glm::dot(d, d);
  if (!(d2 > 0.0)) return 0.0;
  const double cos_e = std::max(0.0, glm::dot(m, d));
  const double cos_r = std::max(0.0, -glm::dot(n, d));
  return area_m2 * cos_e * cos_r / (kPi * d2 * d2);
}

double triangle_solid_angle_from(const Vec3& s, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ra = a - s, rb = b - s, rc = c - s;
  const double la = glm::length(ra), lb = glm::length(rb), lc = glm::length(rc);
  if (!(la > 0.0 && lb > 0.0 && lc > 0.0)) return 0.0;
  return nearfield::triangle_solid_angle(ra / la, rb / lb, rc / lc);
}

}  // namespace luxgrid::calc::indirect
