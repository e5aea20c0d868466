#include "calc/daylight/aperture_integral.h"

#include <cmath>
#include <queue>

#include "geometry/polygon3.h"
#include "geometry/spherical.h"

namespace luxgrid::daylight {
namespace {

double psa(const Triangle3& t, const Vec3& point, const Vec3& normal) {
  const std::array<Vec3, 3> rel{t[0] - point, t[1] - point, t[2] - point};
  return geometry::projected_solid_angle(rel.data(), 3, normal);
}

std::array<Triangle3, 4> children(const Triangle3& t) {
  const Vec3 ab = 0.5 * (t[0] + t[1]), bc = 0.5 * (t[1] + t[2]), ca = 0.5 * (t[2] + t[0]);
  return {Triangle3{t[0], ab, ca}, Triangle3{ab, t[1], bc}, Triangle3{ca, bc, t[2]},
          Triangle3{ab, bc, ca}};
}

struct Leaf {
  Triangle3 triangle;
  std::array<double, 4> child_values;
  double fine = 0.0, error = 0.0;
  bool operator<(const Leaf& other) const { return error < other.error; }
};

}  // namespace

double aperture_projected_solid_angle(const std::vector<Triangle3>& triangles, const Vec3& point,
                                      const Vec3& normal) {
  double sum = 0.0;
  for (const Triangle3& t : triangles) sum += psa(t, point, normal);
  return sum;
}

ApertureIntegral integrate_aperture(const std::vector<Triangle3>& triangles, const Vec3& point,
                                    const Vec3& normal,
                                    const std::function<double(const Vec3&, const Vec3&)>& w,
                                    double relative_tolerance, double absolute_tolerance,
                                    int max_triangles, double max_edge_angle_rad) {
  ApertureIntegral out;
  // The three-node rule on one triangle: its exact projected solid angle times w's mean.
  const auto rule = [&](const Triangle3& t) {
    const double omega = psa(t, point, normal);
    if (!(omega > 0.0)) return 0.0;
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) {
      const Vec3 node = (2.0 / 3.0) * t[k] + (1.0 / 6.0) * (t[(k + 1) % 3] + t[(k + 2) % 3]);
      const Vec3 d = node - point;
      const double length = glm::length(d);
      if (length > 0.0) sum += w(node, d / length);
    }
    out.evaluations += 3;
    return omega * sum / 3.0;
  };
  const auto make_leaf = [&](const Triangle3& t, double coarse) {
    Leaf leaf{t, {}, 0.0, 0.0};
    const auto parts = children(t);
    for (int i = 0; i < 4; ++i)
      leaf.child_values[i] = rule(parts[i]), leaf.fine += leaf.child_values[i];
    leaf.error = std::abs(coarse - leaf.fine);
    return leaf;
  };
  // The start: every triangle cut until its edges subtend at most max_edge_angle_rad (within
  // max_triangles).
  const auto too_wide = [&](const Triangle3& t) {
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = t[k] - point, b = t[(k + 1) % 3] - point;
      const double la = glm::length(a), lb = glm::length(b);
      if (la > 0.0 && lb > 0.0 && angle_between(a / la, b / lb) > max_edge_angle_rad) return true;
    }
    return false;
  };
  std::vector<Triangle3> start, pending(triangles.rbegin(), triangles.rend());
  while (!pending.empty()) {
    const Triangle3 t = pending.back();
    pending.pop_back();
    if (too_wide(t) && static_cast<int>(start.size() + pending.size()) + 4 <= max_triangles / 4) {
      const auto parts = children(t);
      for (int i = 3; i >= 0; --i) pending.push_back(parts[i]);
    } else {
      start.push_back(t);
    }
  }
  std::priority_queue<Leaf> queue;
  double value = 0.0, error = 0.0;
  for (const Triangle3& t : start) {
    const Leaf leaf = make_leaf(t, rule(t));
    value += leaf.fine, error += leaf.error;
    queue.push(leaf);
  }
  while (!queue.empty() && static_cast<int>(queue.size()) + 3 <= max_triangles &&
         error > std::max(absolute_tolerance, relative_tolerance * std::abs(value))) {
    const Leaf worst = queue.top();
    queue.pop();
    value -= worst.fine, error -= worst.error;
    const auto parts = children(worst.triangle);
    for (int i = 0; i < 4; ++i) {
      const Leaf leaf = make_leaf(parts[i], worst.child_values[i]);
      value += leaf.fine, error += leaf.error;
      queue.push(leaf);
    }
  }
  out.triangles = static_cast<int>(queue.size());
  // Added once more from the final triangles: the running sums drift by rounding.
  while (!queue.empty()) {
    out.value += queue.top().fine, out.error_estimate += queue.top().error;
    queue.pop();
  }
  return out;
}

std::vector<Triangle3> clip_to_receiver(const std::vector<Triangle3>& triangles, const Vec3& point,
                                        const Vec3& normal, bool above) {
  std::vector<Triangle3> out;
  const Vec3 up{0.0, 0.0, above ? 1.0 : -1.0};
  for (const Triangle3& t : triangles) {
    geometry::Polygon3 piece(t.begin(), t.end());
    piece = geometry::clip_to_half_space(piece, point, normal);
    if (piece.size() < 3) continue;
    piece = geometry::clip_to_half_space(piece, point, up);
    for (size_t k = 1; k + 1 < piece.size(); ++k) out.push_back({piece[0], piece[k], piece[k + 1]});
  }
  return out;
}

}  // namespace luxgrid::daylight
