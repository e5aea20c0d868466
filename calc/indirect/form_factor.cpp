#include "calc/indirect/form_factor.h"

#include <algorithm>
#include <array>

#include "calc/nearfield/spherical.h"

namespace luxgrid::calc::indirect {

namespace {
// Vertices closer than this to the receiver point are dropped from Lambert's sum: their edges
// subtend no defined angle and (being in the receiver's tangent plane after the horizon clip)
// contribute nothing to the cosine-weighted integral.
constexpr double kMinVertexDistance_m = 1e-12;

// Lambert's sum over the (already horizon-clipped) polygon v[0..count).
double lambert_sum(const Vec3& x, const Vec3& n, const Vec3* v, size_t count) {
  if (count < 3) return 0.0;
  Vec3 sum(0.0);
  Vec3 prev(0.0);
  bool have_prev = false;
  Vec3 first(0.0);
  for (size_t k = 0; k < count; ++k) {
    const Vec3 r = v[k] - x;
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
double lambert_sum(const Vec3& x, const Vec3& n, const Polygon3& clipped) {
  return lambert_sum(x, n, clipped.data(), clipped.size());
}
}  // namespace

double point_polygon_form_factor(const Vec3& x, const Vec3& n, const Polygon3& polygon) {
  // The horizon clip (Sutherland-Hodgman against n . (y - x) >= 0, as clip_to_half_space) into a
  // stack buffer: this runs for every near patch of every receiver, so no heap allocation. A
  // polygon of m vertices clips to at most 2 m.
  constexpr size_t kMaxStack = 16;
  const size_t m = polygon.size();
  if (m < 3) return 0.0;
  if (m > kMaxStack) return lambert_sum(x, n, geometry::clip_to_half_space(polygon, x, n));
  std::array<Vec3, 2 * kMaxStack> clipped;
  std::array<double, kMaxStack> side;
  bool any_front = false, all_front = true;
  for (size_t k = 0; k < m; ++k) {
    side[k] = glm::dot(n, polygon[k] - x);
    any_front = any_front || side[k] >= 0.0;
    all_front = all_front && side[k] >= 0.0;
  }
  if (!any_front) return 0.0;  // wholly behind the receiver: the clip is empty
  if (all_front) return lambert_sum(x, n, polygon.data(), m);
  size_t count = 0;
  for (size_t k = 0; k < m; ++k) {
    const size_t k1 = k + 1 == m ? 0 : k + 1;
    const double dp = side[k], dq = side[k1];
    if (dp >= 0.0) clipped[count++] = polygon[k];
    if ((dp >= 0.0) != (dq >= 0.0))
      clipped[count++] = polygon[k] + (polygon[k1] - polygon[k]) * (dp / (dp - dq));
  }
  return lambert_sum(x, n, clipped.data(), count);
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
                                  const Vec3& m, double area_m2, double diameter_m,
                                  double min_d2) {
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
    sum += point_kernel_pi_per_m2(std::max(0.0, glm::dot(m, d)), std::max(0.0, -glm::dot(n, d)), d2);
  }
  const double f4 = 0.25 * area_m2 * sum / kPi;
  const double f1 = point_kernel_form_factor(x, n, centroid, m, area_m2);
  const double f = (4.0 * f4 - f1) / 3.0;
  return f >= 0.0 ? f : -1.0;
}

double triangle_solid_angle_from(const Vec3& s, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ra = a - s, rb = b - s, rc = c - s;
  const double la = glm::length(ra), lb = glm::length(rb), lc = glm::length(rc);
  if (!(la > 0.0 && lb > 0.0 && lc > 0.0)) return 0.0;
  return nearfield::triangle_solid_angle(ra / la, rb / lb, rc / lc);
}

}  // namespace luxgrid::calc::indirect
