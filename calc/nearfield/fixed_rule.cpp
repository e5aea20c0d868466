#include "calc/nearfield/fixed_rule.h"

#include <algorithm>
#include <cmath>

#include "calc/nearfield/emitter.h"
#include "calc/nearfield/fan_sample.h"
#include "calc/nearfield/models.h"
#include "calc/nearfield/receiver_kernel.h"
#include "geometry/polygon3.h"
#include "geometry/visibility.h"
#include "util/robust_math.h"

namespace luxgrid::nearfield {
FixedRule make_fixed_rule(const std::vector<Vec3>& polygon, double largest_dimension_m) {
  FixedRule rule;
  if (polygon.size() < 3 || !(largest_dimension_m > 0.0)) return rule;
  Vec3 lo(INFINITY), hi(-INFINITY);
  for (const Vec3& v : polygon) lo = glm::min(lo, v), hi = glm::max(hi, v);
  const auto cells = [&](double extent) {
    return std::min(pieces_of_at_most(kFixedRuleCellsPerD * extent / largest_dimension_m),
                    kFixedRuleMaxCells);
  };
  const int nx = cells(hi.x - lo.x), ny = cells(hi.y - lo.y);
  double total = 0.0;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      const double x0 = lo.x + (hi.x - lo.x) * i / nx, x1 = lo.x + (hi.x - lo.x) * (i + 1) / nx;
      const double y0 = lo.y + (hi.y - lo.y) * j / ny, y1 = lo.y + (hi.y - lo.y) * (j + 1) / ny;
      // The cell [x0, x1] x [y0, y1] of the opening (z = 0 in the luminaire frame).
      geometry::Polygon3 part =
          geometry::clip_to_half_space(polygon, Vec3(x0, 0.0, 0.0), Vec3(1.0, 0.0, 0.0));
      part = geometry::clip_to_half_space(part, Vec3(x1, 0.0, 0.0), Vec3(-1.0, 0.0, 0.0));
      part = geometry::clip_to_half_space(part, Vec3(0.0, y0, 0.0), Vec3(0.0, 1.0, 0.0));
      part = geometry::clip_to_half_space(part, Vec3(0.0, y1, 0.0), Vec3(0.0, -1.0, 0.0));
      if (part.size() < 3) continue;
      const double a = glm::length(geometry::area_vector(part));
      if (!(a > 0.0)) continue;
      const Vec3 c = geometry::polygon_centroid(part);
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
    // Each node a point source carrying its share of the intensity (far_field.cpp's formula).
    const double node_lx = point_source_illuminance(*e.distribution, e.world_to_local,
                                                    e.rule_nodes[j], point, receiver);
    if (!(node_lx > 0.0)) continue;
    if (occluder && !occluder->visible(e.rule_nodes[j], point)) continue;
    sum += e.rule_weights[j] * node_lx;
  }
  return sanitize_illuminance(sum);
}

}  // namespace luxgrid::nearfield
