#include "calc/nearfield/fixed_rule.h"

#include <algorithm>
#include <cmath>

#include "calc/nearfield/emitter.h"
#include "calc/nearfield/fan_sample.h"
#include "geometry/visibility.h"
#include "calc/nearfield/receiver_kernel.h"

namespace luxgrid::nearfield {
namespace {

// Sutherland-Hodgman: the part of `poly` (x, y) with s * coordinate[axis] <= s * limit.
std::vector<Vec3> clip_half_plane(const std::vector<Vec3>& poly, int axis, double limit, double s) {
  std::vector<Vec3> out;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = poly[i];
    const Vec3& b = poly[(i + 1) % n];
    const double fa = s * (a[axis] - limit), fb = s * (b[axis] - limit);
    if (fa <= 0.0) out.push_back(a);
    if ((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0)) out.push_back(a + (fa / (fa - fb)) * (b - a));
  }
  return out;
}

// Area and area centroid of a planar polygon in z = 0 (shoelace).
double area_and_centroid(const std::vector<Vec3>& p, Vec3& centroid) {
  double a2 = 0.0;
  Vec3 c{0.0};
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& u = p[i];
    const Vec3& v = p[(i + 1) % p.size()];
    const double cross = u.x * v.y - v.x * u.y;
    a2 += cross;
    c += cross * (u + v);
  }
  if (std::abs(a2) > 0.0) centroid = Vec3(c.x / (3.0 * a2), c.y / (3.0 * a2), 0.0);
  return 0.5 * std::abs(a2);
}

}  // namespace

FixedRule make_fixed_rule(const std::vector<Vec3>& polygon, double largest_dimension_m) {
  FixedRule rule;
  if (polygon.size() < 3 || !(largest_dimension_m > 0.0)) return rule;
  Vec3 lo(INFINITY), hi(-INFINITY);
  for (const Vec3& v : polygon) lo = glm::min(lo, v), hi = glm::max(hi, v);
  const auto cells = [&](double extent) {
    return std::clamp(static_cast<int>(std::ceil(kFixedRuleCellsPerD * extent / largest_dimension_m - 1e-9)), 1,
                      kFixedRuleMaxCells);
  };
  const int nx = cells(hi.x - lo.x), ny = cells(hi.y - lo.y);
  double total = 0.0;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      const double x0 = lo.x + (hi.x - lo.x) * i / nx, x1 = lo.x + (hi.x - lo.x) * (i + 1) / nx;
      const double y0 = lo.y + (hi.y - lo.y) * j / ny, y1 = lo.y + (hi.y - lo.y) * (j + 1) / ny;
      std::vector<Vec3> part = clip_half_plane(polygon, 0, x0, -1.0);
      part = clip_half_plane(part, 0, x1, 1.0);
      part = clip_half_plane(part, 1, y0, -1.0);
      part = clip_half_plane(part, 1, y1, 1.0);
      if (part.size() < 3) continue;
      Vec3 c{0.0};
      const double a = area_and_centroid(part, c);
      if (!(a > 0.0)) continue;
      rule.nodes_local.push_back(c);
      rule.weights.push_back(a);
      total += a;
    }
  for (double& w : rule.weights) w /= total;
  return rule;
}

double fixed_rule_illuminance(const Emitter& e, const Vec3& point, const Receiver& receiver,
                              const geometry::Visibility* occluder) {
  double sum = 0.0;
  for (std::size_t j = 0; j < e.rule_nodes.size(); ++j) {
    const Vec3 r = point - e.rule_nodes[j];  // node -> receiver
    const double d2 = glm::dot(r, r);
    if (!(d2 > 0.0)) continue;
    const Vec3 w = r / std::sqrt(d2);
    const double g = receiver_weight(receiver, -w);
    if (!(g > 0.0)) continue;
    if (occluder && !occluder->visible(e.rule_nodes[j], point)) continue;
    sum += e.rule_weights[j] * e.intensity_towards(w) * g / d2;
  }
  return sanitize_illuminance(sum);
}

}  // namespace luxgrid::nearfield
