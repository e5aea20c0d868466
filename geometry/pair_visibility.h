#pragma once
// One pair's view of the occlusion test: the segments a calculation traces between two elements
// (a luminaire's opening and a receiver point, in calc/direct) get the pair's shaft verdict
// (geometry/shaft.h) instead of one ray each, once the pair has asked for more than a few
// segments. The verdict is a proof for every segment between the two elements, so each answer
// equals the occlusion test's, and results stay bit for bit the same (docs/performance.md).
//
// Lazy because classifying costs about as much as a few rays: a pair the far field serves asks
// one segment (and a penumbra check eight more) and never pays for it; a pair the near-field
// models integrate asks one per quadrature node, hundreds to thousands at `reference`.
//
// One object per pair and thread: it counts the segments asked (not thread-safe by design, unlike
// the Visibility it wraps).
#include <span>

#include "geometry/shaft.h"
#include "geometry/visibility.h"

namespace luxgrid::geometry {

class PairVisibility final : public Visibility {
 public:
  // The segments before the pair is classified: a far-field pair's centroid and penumbra tests
  // (calc/nearfield/illuminance.cpp: 1 + 8) stay with the occlusion test.
  static constexpr int kSegmentsBeforeClassifying = 9;

  // `a`, `b`: the elements' corners (geometry/shaft.h), alive as long as this object.
  PairVisibility(const Visibility& exact, std::span<const Vec3> a, std::span<const Vec3> b)
      : exact_(exact), a_(a), b_(b), box_a_(bounds(a)), box_b_(bounds(b)) {}

  bool visible(const Vec3& from, const Vec3& to) const override {
    if (!classified_ && ++segments_ > kSegmentsBeforeClassifying) {
      verdict_ = exact_.classify(a_, b_);
      classified_ = true;
    }
    // A segment outside the elements' boxes is not the pair's: the occlusion test decides it.
    if (verdict_ != Shaft::partial && ((within(from, box_a_) && within(to, box_b_)) ||
                                       (within(from, box_b_) && within(to, box_a_))))
      return verdict_ == Shaft::visible;
    return exact_.visible(from, to);
  }
  Shaft classify(std::span<const Vec3> a, std::span<const Vec3> b) const override {
    return exact_.classify(a, b);
  }
  Shaft classify_within(std::span<const Vec3> a, std::span<const Vec3> b, const ShaftFaces& among,
                        ShaftFaces& undecided) const override {
    return exact_.classify_within(a, b, among, undecided);
  }
  // A caller that narrows classified the segment's shaft itself: not counted towards the pair's
  // verdict, which answers only when already known.
  bool visible_among(const Vec3& from, const Vec3& to, const ShaftFaces& faces) const override {
    if (verdict_ != Shaft::partial && ((within(from, box_a_) && within(to, box_b_)) ||
                                       (within(from, box_b_) && within(to, box_a_))))
      return verdict_ == Shaft::visible;
    return exact_.visible_among(from, to, faces);
  }

  // The verdict once classified (`partial` before).
  Shaft verdict() const { return verdict_; }

 private:
  static Box3 bounds(std::span<const Vec3> e) {
    Box3 box{e.empty() ? Vec3(0.0) : e.front(), e.empty() ? Vec3(0.0) : e.front()};
    for (const Vec3& p : e) box.lo = glm::min(box.lo, p), box.hi = glm::max(box.hi, p);
    return box;
  }
  // Within the box grown by the rounding allowance of segment ends (kShaftSlack_m).
  static bool within(const Vec3& p, const Box3& box) {
    for (int k = 0; k < 3; ++k)
      if (p[k] < box.lo[k] - kShaftSlack_m || p[k] > box.hi[k] + kShaftSlack_m) return false;
    return true;
  }

  const Visibility& exact_;
  std::span<const Vec3> a_, b_;
  Box3 box_a_, box_b_;
  mutable int segments_ = 0;
  mutable bool classified_ = false;
  mutable Shaft verdict_ = Shaft::partial;
};

}  // namespace luxgrid::geometry
