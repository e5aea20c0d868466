// The converging reference for any distribution: globally adaptive cubature
// of the area form of the illuminance (Luksch et al. 2020 Eq. 1 without the BRDF),
//   E = (1/A) * integral over the clipped polygon of I(-w) g(w) / d^2 dA,
// g the receiver's weight (receiver_kernel.h: cos_r for a plane, sin(eps) / pi for a cylinder),
// which shares no code with the solid-angle models except the fan (for the split at the CP,
// where the integrand peaks).
#include <algorithm>
#include <cmath>
#include <queue>
#include <vector>

#include "calc/nearfield/fan_sample.h"
#include "calc/nearfield/models.h"
#include "calc/nearfield/receiver_kernel.h"

namespace luxgrid::nearfield {
namespace {

// Radon's 7-point degree-5 rule on a triangle (Stroud T2:5-1): barycentric points and weights.
const double kS15 = std::sqrt(15.0);
const double kA1 = (6.0 - kS15) / 21.0, kB1 = (9.0 + 2.0 * kS15) / 21.0;
const double kA2 = (6.0 + kS15) / 21.0, kB2 = (9.0 - 2.0 * kS15) / 21.0;
const double kW0 = 9.0 / 40.0, kW1 = (155.0 - kS15) / 1200.0, kW2 = (155.0 + kS15) / 1200.0;

// Absolute floor of the stopping test, as a fraction of the first estimate: a receiver that
// sees only a sliver would otherwise chase digits of a value that is zero for all purposes.
constexpr double kAbsoluteFloorRelative = 1e-14;

// Peak guard (Cubature::make): a vertex value above this many times the largest interior node
// value of the triangle's children marks a peak the interior rule cannot see. Smooth integrands
// stay far below it once a triangle is smaller than the receiver's distance (the geometric
// 1 / d^2 peak at the foot point changes by less than 4x across such a triangle).
constexpr double kPeakRatio = 4.0;

struct Integrand {
  const Emitter* e;
  Receiver what;
  double inv_area;
  const geometry::Visibility* occluder = nullptr;  // per-sample visibility (fan_sample.h)
  Vec3 receiver{0.0};                              // unshifted receiver, world: segment end
  Vec3 origin{0.0};                                // shifted receiver, world: origin of `r`
  double operator()(const Vec3& r) const {
    const double d2 = glm::dot(r, r);
    if (!(d2 > 0.0)) return 0.0;
    const Vec3 w = r / std::sqrt(d2);
    const double weight = receiver_weight(what, w);
    if (!(weight > 0.0)) return 0.0;
    const double value = e->intensity_towards(-w) * weight / d2 * inv_area;
    if (occluder && value != 0.0) {
      const Vec3 p = origin + r;
      if (!occluder->visible(p + kVisibilityInsetRelative * (e->centroid - p), receiver))
        return 0.0;
    }
    return value;
  }
};

struct Tri {
  Vec3 a, b, c;
  double fine = 0.0;                       // sum of the four children's 7-point values
  double error = 0.0;                      // |7-point value of the parent - fine|
  double child[4] = {0.0, 0.0, 0.0, 0.0};  // the children's 7-point values, in split order
  bool operator<(const Tri& o) const { return error < o.error; }
};

class Cubature {
 public:
  explicit Cubature(const Integrand& f) : f_(f) {}
  // The 7-point value of the triangle; `node_max` (optional) grows to its largest node value.
  double rule(const Vec3& a, const Vec3& b, const Vec3& c, double* node_max = nullptr) {
    evaluations_ += 7;
    const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
    double largest = 0.0;
    auto at = [&](double x, double y, double z) {
      const double v = f_(x * a + y * b + z * c);
      largest = std::max(largest, v);
      return v;
    };
    const double s = kW0 * at(1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0) +
                     kW1 * (at(kA1, kA1, kB1) + at(kA1, kB1, kA1) + at(kB1, kA1, kA1)) +
                     kW2 * (at(kA2, kA2, kB2) + at(kA2, kB2, kA2) + at(kB2, kA2, kA2));
    if (node_max) *node_max = std::max(*node_max, largest);
    return area * s;
  }
  Tri make(const Vec3& a, const Vec3& b, const Vec3& c, double coarse) {
    const Vec3 ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
    Tri t{a, b, c};
    double node_max = 0.0;
    t.child[0] = rule(a, ab, ca, &node_max);
    t.child[1] = rule(ab, b, bc, &node_max);
    t.child[2] = rule(ca, bc, c, &node_max);
    t.child[3] = rule(ab, bc, ca, &node_max);
    t.fine = t.child[0] + t.child[1] + t.child[2] + t.child[3];
    t.error = std::abs(t.fine - coarse);
    // Peak guard. Every node of the 7-point rule is interior, so a peak narrower than the
    // triangle that sits at a vertex is invisible to both the coarse and the fine value, and
    // their difference says "converged" on a wrong value. It happens where it matters: the fan's
    // apex is the receiver's foot point, where a downlight's beam lands on a receiver right
    // under it (a 5-degree spot 0.1 m below a 1 x 1 m opening: the rule alone gave 310 lx for
    // 458.5 lx, tests/nearfield/reference_peak_test.cpp). So the vertices are looked at too (3 more
    // lookups): when one exceeds kPeakRatio x every interior node, the triangle may hide up to
    // area x that value, and that is its error until it is split fine enough.
    evaluations_ += 3;
    const double vertex_max = std::max({f_(a), f_(b), f_(c)});
    if (vertex_max > kPeakRatio * node_max) {
      const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
      t.error = std::max(t.error, area * vertex_max);
    }
    return t;
  }
  Tri make(const Vec3& a, const Vec3& b, const Vec3& c) { return make(a, b, c, rule(a, b, c)); }
  std::int64_t evaluations() const { return evaluations_; }

 private:
  const Integrand& f_;
  std::int64_t evaluations_ = 0;
};

}  // namespace

ReferenceResult reference_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal,
                                      double rel_tol, std::int64_t max_evaluations,
                                      const geometry::Visibility* occluder) {
  return reference_illuminance(e, point, Receiver::planar(normal), rel_tol, max_evaluations,
                               occluder);
}

ReferenceResult reference_illuminance(const Emitter& e, const Vec3& point, const Receiver& receiver,
                                      double rel_tol, std::int64_t max_evaluations,
                                      const geometry::Visibility* occluder) {
  ReferenceResult result;
  if (e.is_point()) {
    if (!occluder || occluder->visible(e.centroid, point))
      result.illuminance_lx = far_field_illuminance(e, point, receiver);
    result.converged = true;
    return result;
  }
  // A cylinder has no horizon (horizon_normal() is 0): the fan then covers the whole opening.
  const ReceiverFan fan = build_fan(e, point, receiver.horizon_normal(), horizon_shift_m(e));
  if (fan.triangles == 0) {
    result.converged = true;
    return result;
  }
  const Integrand f{&e, receiver, 1.0 / e.area_m2, occluder, point, fan.receiver};
  Cubature cubature(f);
  std::priority_queue<Tri> queue;
  double value = 0.0, error = 0.0;
  for (int i = 0; i < fan.triangles; ++i) {
    Tri t = cubature.make(fan.apex, fan.rim[i], fan.rim[i + 1]);
    value += t.fine;
    error += t.error;
    queue.push(t);
  }
  const double floor = kAbsoluteFloorRelative * std::abs(value);
  while (!queue.empty() && error > std::max(rel_tol * std::abs(value), floor) &&
         cubature.evaluations() < max_evaluations) {
    const Tri t = queue.top();
    queue.pop();
    value -= t.fine;
    error -= t.error;
    const Vec3 ab = 0.5 * (t.a + t.b), bc = 0.5 * (t.b + t.c), ca = 0.5 * (t.c + t.a);
    // The parent kept its children's 7-point values (its `fine`): each child only adds its own
    // four children (28 lookups, not 35).
    for (const Tri& child :
         {cubature.make(t.a, ab, ca, t.child[0]), cubature.make(ab, t.b, bc, t.child[1]),
          cubature.make(ca, bc, t.c, t.child[2]), cubature.make(ab, bc, ca, t.child[3])}) {
      value += child.fine;
      error += child.error;
      queue.push(child);
    }
  }
  error = std::max(error, 0.0);
  result.illuminance_lx = sanitize_illuminance(value);
  result.error_estimate_lx = error;
  result.evaluations = cubature.evaluations();
  result.converged = error <= std::max(rel_tol * std::abs(value), floor);
  return result;
}

}  // namespace luxgrid::nearfield
