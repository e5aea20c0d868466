#include "geometry/polygon3.h"

#include <algorithm>
#include <cmath>

namespace luxgrid::geometry {

Vec3 area_vector(const Polygon3& p) {
  Vec3 s(0.0);
  for (size_t i = 0, n = p.size(); i < n; ++i) s += glm::cross(p[i], p[(i + 1) % n]);
  return 0.5 * s;
}

Vec3 polygon_centroid(const Polygon3& p) {
  // Fan from the first corner; triangle centroids weighted by their (signed, projected) area.
  if (p.empty()) return Vec3(0.0);
  const Vec3 n = area_vector(p);
  const double nn = glm::length(n);
  Vec3 mean(0.0);
  for (const auto& v : p) mean += v;
  mean /= static_cast<double>(p.size());
  if (!(nn > 0.0)) return mean;
  const Vec3 u = n / nn;
  Vec3 c(0.0);
  double a = 0.0;
  for (size_t i = 1; i + 1 < p.size(); ++i) {
    const double t = 0.5 * glm::dot(u, glm::cross(p[i] - p[0], p[i + 1] - p[0]));
    c += t * (p[0] + p[i] + p[i + 1]) / 3.0;
    a += t;
  }
  return std::abs(a) > 0.0 ? c / a : mean;
}

double polygon_diameter(const Polygon3& p) {
  double d = 0.0;
  for (size_t i = 0; i < p.size(); ++i)
    for (size_t j = i + 1; j < p.size(); ++j) d = std::max(d, glm::length(p[i] - p[j]));
  return d;
}

Polygon3 clip_to_half_space(const Polygon3& poly, const Vec3& origin, const Vec3& n) {
  Polygon3 out;
  const int count = static_cast<int>(poly.size());
  if (count < 3) return out;
  std::vector<Vec3> rel(poly.size());
  std::vector<double> h(poly.size());
  detail::clip_relative(
      poly.data(), count, origin, n, rel, h, [&](const Vec3& p) { out.push_back(origin + p); },
      [] { return true; });
  return out;
}

}  // namespace luxgrid::geometry
