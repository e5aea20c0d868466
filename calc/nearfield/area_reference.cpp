// The converging reference for any distribution: globally adaptive cubature
// of the area form of the illuminance (Luksch et al. 2020 Eq. 1 without the BRDF),
//   E = (1/A) * integral over the clipped polygon of I(-w) g(w) / d^2 dA,
// g the receiver's weight (receiver_kernel.h: cos_r for a plane, sin(eps) / pi for a cylinder),
// which shares no code with the solid-angle models except the fan (for the split at the CP,
// where the integrand peaks).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <queue>
#include <span>
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

// Shadow guard (Cubature::make). A shadow edge that cuts off a corner of a triangle, or a strip
// along one of its sides, can miss every node of its 7-point rule; the coarse and fine values then
// agree on a wrong value. The corners see it: one visible where every node is hidden, or hidden
// where every node is visible. A straight edge (every shadow edge is, at the scale of a small
// triangle: an occluder's edge seen from the receiver) can keep at most this share of a
// triangle's area from the rule's 7 nodes (11.6 %, the strip along a side, measured over 2e5
// directions of the line), so that share x the largest unoccluded value is the error of each
// child where the corners and nodes disagree. Judged by the peak guard instead (area x value, as
// before), every triangle along a shadow edge kept its whole area as error, and refinement crept
// along the edges at first order until the lookup budget ran out (examples/lshape: 71 of 1008
// pairs of a coarse grid at 4 million lookups, docs/accuracy.md).
constexpr double kSliverShare = 0.12;

// A triangle whose nodes are partly seen and partly hidden straddles a shadow edge: a step, on
// which the fine value converges at first order only, so |fine - coarse| is about its error, and
// below it as often as above. Doubled it covers it: on CIE 171 case 5.7 (cases/, an exact value,
// the shadow edge across the whole opening) the undoubled estimate at 1e-4 said 1.0e-4 where the
// error was 1.8e-4; doubled, it says 1.0e-4 where the error is 6.3e-5.
constexpr double kShadowEdgeFactor = 2.0;

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
  // The integrand as if nothing were in the way (the peak guard's probe).
  double unoccluded(const Vec3& r) const {
    const double d2 = glm::dot(r, r);
    if (!(d2 > 0.0)) return 0.0;
    const Vec3 w = r / std::sqrt(d2);
    const double weight = receiver_weight(what, w);
    if (!(weight > 0.0)) return 0.0;
    return e->intensity_towards(-w) * weight / d2 * inv_area;
  }
  // unoccluded(r[k]) into out[k] for k < n (at most kMaxBatch): the same formula, the
  // intensities looked up together (IntensityDistribution::intensities: the same values, a table's
  // angles computed as lanes).
  static constexpr int kMaxBatch = 28;
  void unoccluded(const Vec3* r, int n, double* out) const {
    double x[kMaxBatch], y[kMaxBatch], z[kMaxBatch], weight[kMaxBatch], d2[kMaxBatch],
        cd[kMaxBatch];
    int index[kMaxBatch], m = 0;
    for (int k = 0; k < n; ++k) {
      out[k] = 0.0;
      d2[m] = glm::dot(r[k], r[k]);
      if (!(d2[m] > 0.0)) continue;
      const Vec3 w = r[k] / std::sqrt(d2[m]);
      weight[m] = receiver_weight(what, w);
      if (!(weight[m] > 0.0)) continue;
      const Vec3 local = e->world_to_local * -w;  // as intensity_towards(-w) turns it
      x[m] = local.x, y[m] = local.y, z[m] = local.z, index[m++] = k;
    }
    e->distribution->intensities(x, y, z, static_cast<size_t>(m), cd);
    for (int j = 0; j < m; ++j) out[index[j]] = cd[j] * weight[j] / d2[j] * inv_area;
  }
  // What every segment from the triangle (a, b, c) (relative to `origin`, moved inwards as the
  // nodes are) to the receiver says: a proof for all of its nodes (geometry/shaft.h). Within the
  // faces `among` that the classification of a triangle holding it left undecided; the faces it
  // leaves go to `undecided`, and decide its nodes (geometry/visibility.h, ShaftFaces).
  geometry::Shaft classify(const Vec3& a, const Vec3& b, const Vec3& c,
                           const geometry::ShaftFaces& among,
                           geometry::ShaftFaces& undecided) const {
    if (!occluder) return geometry::Shaft::visible;
    Vec3 corners[3] = {origin + a, origin + b, origin + c};
    for (Vec3& p : corners) p += kVisibilityInsetRelative * (e->centroid - p);
    return occluder->classify_within(std::span<const Vec3>(corners, 3),
                                     std::span<const Vec3>(&receiver, 1), among, undecided);
  }
  // `value` (the unoccluded integrand at `r`) where the receiver sees the point, else 0; `faces`:
  // what the classification of a triangle holding the point left undecided.
  double occluded(const Vec3& r, double value, const geometry::ShaftFaces& faces) const {
    if (occluder && value != 0.0) {
      const Vec3 p = origin + r;
      if (!occluder->visible_among(p + kVisibilityInsetRelative * (e->centroid - p), receiver,
                                   faces))
        return 0.0;
    }
    return value;
  }
};

// The integrand at a point: as if nothing were in the way, and as the receiver sees it.
struct Sample {
  double open = 0.0, seen = 0.0;
};

// What the nodes of a triangle's rules saw: the largest unoccluded value, and whether any node
// with light was visible and any hidden.
struct NodeSummary {
  double open_max = 0.0;
  bool any_seen = false, any_hidden = false;
};

struct Tri {
  Vec3 a, b, c;
  Sample va, vb, vc;                       // the integrand at a, b, c (the guards')
  Sample vab, vbc, vca;                    // and at the midpoints of the sides (the children's)
  double fine = 0.0;                       // sum of the four children's 7-point values
  double error = 0.0;                      // |7-point value of the parent - fine|
  double child[4] = {0.0, 0.0, 0.0, 0.0};  // the children's 7-point values, in split order
  geometry::Shaft shaft = geometry::Shaft::partial;  // what the receiver sees of it, if proven
  geometry::ShaftFaces faces;  // where partial, the faces that decide its nodes
};

// The triangles waiting to be split, the largest error first. The heap holds each triangle's
// error and its slot in `slots` (a freed slot is reused): its sifts move 16 bytes, not a whole
// triangle, through the same comparisons of the same errors as a heap of triangles, so the
// triangles come out in the same order.
class SplitQueue {
 public:
  void push(const Tri& t) {
    uint32_t slot = 0;
    if (free_.empty()) {
      slot = static_cast<uint32_t>(slots_.size());
      slots_.push_back(t);
    } else {
      slot = free_.back();
      free_.pop_back();
      slots_[slot] = t;
    }
    heap_.push({t.error, slot});
  }
  bool empty() const { return heap_.empty(); }
  // The triangle with the largest error, valid until release().
  const Tri& top() const { return slots_[heap_.top().slot]; }
  // Removes the top triangle; its slot is taken by the next push.
  void release() {
    free_.push_back(heap_.top().slot);
    heap_.pop();
  }

 private:
  struct Entry {
    double error;
    uint32_t slot;
    bool operator<(const Entry& o) const { return error < o.error; }
  };
  std::priority_queue<Entry> heap_;
  std::vector<Tri> slots_;
  std::vector<uint32_t> free_;
};

class Cubature {
 public:
  explicit Cubature(const Integrand& f) : f_(f) {}
  // The 7-point values of `count` triangles (corners `tri[k]`) into `value[k]`, their nodes into
  // `nodes[k]`: rule() on each, the 7 x count intensities looked up together.
  template <int count>
  void rules(const Vec3 (&tri)[count][3], double (&value)[count], NodeSummary (&nodes)[count]) {
    static_assert(7 * count <= Integrand::kMaxBatch);
    evaluations_ += 7 * count;
    Vec3 r[7 * count];
    for (int k = 0; k < count; ++k) {
      const Vec3 &a = tri[k][0], &b = tri[k][1], &c = tri[k][2];
      const auto at = [&](double x, double y, double z) { return x * a + y * b + z * c; };
      Vec3* q = r + 7 * k;
      q[0] = at(1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0);
      q[1] = at(kA1, kA1, kB1), q[2] = at(kA1, kB1, kA1), q[3] = at(kB1, kA1, kA1);
      q[4] = at(kA2, kA2, kB2), q[5] = at(kA2, kB2, kA2), q[6] = at(kB2, kA2, kA2);
    }
    double open[7 * count];
    f_.unoccluded(r, 7 * count, open);
    for (int k = 0; k < count; ++k) {
      NodeSummary here;
      double seen[7];
      for (int j = 0; j < 7; ++j) {
        const Sample v = occluded(r[7 * k + j], open[7 * k + j]);
        here.open_max = std::max(here.open_max, v.open);
        here.any_seen |= v.seen > 0.0;
        here.any_hidden |= v.open > 0.0 && !(v.seen > 0.0);
        seen[j] = v.seen;
      }
      const Vec3 &a = tri[k][0], &b = tri[k][1], &c = tri[k][2];
      const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
      const double sum =
          kW0 * seen[0] + kW1 * (seen[1] + seen[2] + seen[3]) + kW2 * (seen[4] + seen[5] + seen[6]);
      nodes[k].open_max = std::max(nodes[k].open_max, here.open_max);
      nodes[k].any_seen |= here.any_seen;
      nodes[k].any_hidden |= here.any_hidden;
      value[k] = area * sum;
    }
  }
  // The 7-point value of the triangle.
  double rule(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 tri[1][3] = {{a, b, c}};
    double value[1];
    NodeSummary nodes[1];
    rules(tri, value, nodes);
    return value[0];
  }
  // `coarse`: the triangle's own 7-point value; `va`, `vb`, `vc`: the integrand at its vertices
  // (a vertex is shared with the parent or a sibling: looked up once).
  // `shaft`: the parent's verdict (a proof holds for its children); partial: asked here, within
  // the faces the parent's left (`faces`).
  Tri make(const Vec3& a, const Vec3& b, const Vec3& c, double coarse, const Sample& va,
           const Sample& vb, const Sample& vc, geometry::Shaft shaft,
           const geometry::ShaftFaces& faces) {
    // A triangle the receiver provably sees whole (or not at all) needs no segment per node: the
    // shaft's verdict answers each exactly as the occlusion test would (geometry/shaft.h).
    shaft_ = shaft == geometry::Shaft::partial ? f_.classify(a, b, c, faces, faces_) : shaft;
    return made(a, b, c, coarse, va, vb, vc);
  }
  Tri make(const Vec3& a, const Vec3& b, const Vec3& c) {
    shaft_ = f_.classify(a, b, c, geometry::ShaftFaces{}, faces_);
    const double coarse = rule(a, b, c);
    const Sample va = vertex(a), vb = vertex(b), vc = vertex(c);
    return made(a, b, c, coarse, va, vb, vc);
  }
  // The four children of `t`, in split order (the parent kept their 7-point values, its `child`,
  // and the integrand at their corners).
  std::array<Tri, 4> split(const Tri& t) {
    const Vec3 ab = 0.5 * (t.a + t.b), bc = 0.5 * (t.b + t.c), ca = 0.5 * (t.c + t.a);
    return {make(t.a, ab, ca, t.child[0], t.va, t.vab, t.vca, t.shaft, t.faces),
            make(ab, t.b, bc, t.child[1], t.vab, t.vb, t.vbc, t.shaft, t.faces),
            make(ca, bc, t.c, t.child[2], t.vca, t.vbc, t.vc, t.shaft, t.faces),
            make(ab, bc, ca, t.child[3], t.vab, t.vbc, t.vca, t.shaft, t.faces)};
  }
  std::int64_t evaluations() const { return evaluations_; }

 private:
  // The triangle classified (shaft_, faces_): its children's rules, the midpoints, the guards.
  Tri made(const Vec3& a, const Vec3& b, const Vec3& c, double coarse, const Sample& va,
           const Sample& vb, const Sample& vc) {
    const Vec3 ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
    Tri t;
    t.a = a, t.b = b, t.c = c, t.va = va, t.vb = vb, t.vc = vc;
    t.vab = vertex(ab), t.vbc = vertex(bc), t.vca = vertex(ca);
    t.shaft = shaft_;
    t.faces = faces_;
    NodeSummary nodes[4];
    const Vec3 children[4][3] = {{a, ab, ca}, {ab, b, bc}, {ca, bc, c}, {ab, bc, ca}};
    rules(children, t.child, nodes);
    t.fine = t.child[0] + t.child[1] + t.child[2] + t.child[3];
    t.error = std::abs(t.fine - coarse);
    bool seen = false, hidden = false;
    for (const NodeSummary& n : nodes) seen |= n.any_seen, hidden |= n.any_hidden;
    if (seen && hidden) t.error *= kShadowEdgeFactor;
    const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
    // Peak guard. Every node of the 7-point rule is interior, so a peak narrower than the
    // triangle that sits at a vertex is invisible to both the coarse and the fine value, and
    // their difference says "converged" on a wrong value. It happens where it matters: the fan's
    // apex is the receiver's foot point, where a downlight's beam lands on a receiver right
    // under it (a 5-degree spot 0.1 m below a 1 x 1 m opening: the rule alone gave 310 lx for
    // 458.5 lx, tests/nearfield/reference_peak_test.cpp). So the vertices are looked at too:
    // when a visible one exceeds kPeakRatio x every interior node, the triangle may hide up to
    // area x that value, and that is its error until it is split fine enough. The nodes are
    // taken unoccluded: a peak is the beam's, and a shadow is the shadow guard's.
    const double node_max =
        std::max({nodes[0].open_max, nodes[1].open_max, nodes[2].open_max, nodes[3].open_max});
    const double vertex_max = std::max({va.seen, vb.seen, vc.seen});
    if (vertex_max > kPeakRatio * node_max) t.error = std::max(t.error, area * vertex_max);
    // Shadow guard, per child: see kSliverShare.
    const Sample* corners[4][3] = {{&t.va, &t.vab, &t.vca},
                                   {&t.vab, &t.vb, &t.vbc},
                                   {&t.vca, &t.vbc, &t.vc},
                                   {&t.vab, &t.vbc, &t.vca}};
    double sliver = 0.0;
    for (int k = 0; k < 4; ++k) {
      bool corner_seen = false, corner_hidden = false;
      double open_max = nodes[k].open_max;
      for (const Sample* v : corners[k]) {
        corner_seen |= v->seen > 0.0;
        corner_hidden |= v->open > 0.0 && !(v->seen > 0.0);
        open_max = std::max(open_max, v->open);
      }
      if ((corner_seen && !nodes[k].any_seen) || (corner_hidden && !nodes[k].any_hidden))
        sliver += kSliverShare * 0.25 * area * open_max;
    }
    t.error = std::max(t.error, sliver);
    return t;
  }
  Sample sample(const Vec3& r) const { return occluded(r, f_.unoccluded(r)); }
  // The sample at `r` whose unoccluded integrand is `open`.
  Sample occluded(const Vec3& r, double open) const {
    switch (shaft_) {
      case geometry::Shaft::visible: return {open, open};
      case geometry::Shaft::hidden: return {open, 0.0};
      case geometry::Shaft::partial: break;
    }
    return {open, f_.occluded(r, open, faces_)};
  }
  Sample vertex(const Vec3& r) {
    ++evaluations_;
    return sample(r);
  }
  const Integrand& f_;
  std::int64_t evaluations_ = 0;
  geometry::Shaft shaft_ = geometry::Shaft::partial;  // the triangle being sampled
  geometry::ShaftFaces faces_;                        // and the faces that decide its nodes
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
  SplitQueue queue;
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
    const Tri& t = queue.top();
    value -= t.fine;
    error -= t.error;
    // The parent kept its children's 7-point values (its `fine`) and its vertex values: each
    // child only adds its own four children (28 lookups, not 35) and the split's three midpoints.
    const std::array<Tri, 4> children = cubature.split(t);
    queue.release();
    for (const Tri& child : children) {
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
