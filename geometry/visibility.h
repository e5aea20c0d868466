#pragma once
// The one visibility interface of luxgrid: does light travel freely between two points? Direct
// light (calc/direct, through the near-field models per quadrature node), indirect light
// (calc/indirect: first bounce, form factors, final gather) and glare (calc/glare) all ask it
// through a `const Visibility*`, where null means "nothing blocks light" and costs nothing.
// Plain doubles, no CGAL: calc/nearfield (the hot path, built without CGAL) uses it too. The
// scene's implementation is the AABB tree of geometry/occlusion.h; tests implement their own.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/box3.h"
#include "util/robust_math.h"

namespace luxgrid::geometry {

// What every segment between two elements says (geometry/shaft.h).
enum class Shaft { visible, hidden, partial };

// The faces of a visibility test that may cross some segment of a shaft: those its
// classification left undecided (Visibility::classify_within), as the test's own face numbers.
// Every other face provably crosses none of the shaft's segments, so a segment of the shaft is
// blocked exactly when one of these crosses it: a few face tests instead of a trace through the
// scene (Visibility::visible_among). A sub-shaft (a part of one element) classified within them
// keeps fewer still, so the faces left shrink as an integration refines towards a shadow edge.
struct ShaftFaces {
  static constexpr int kMaxFaces = 12;
  // The faces, or -1 when the shaft is not narrowed (more than kMaxFaces, or a test that does not
  // narrow): every face of the test may cross a segment.
  int count = -1;
  std::array<uint32_t, kMaxFaces> face{};
  bool narrowed() const { return count >= 0; }
};

class Visibility {
 public:
  virtual ~Visibility() = default;
  // True when nothing lies between `from` and `to` (m, world). Symmetric. Called from worker
  // threads: implementations must be thread-safe.
  virtual bool visible(const Vec3& from, const Vec3& to) const = 0;
  // visible(from, to[i]) into seen[i] for every i (to.size() at most kMaxSegmentsFrom): the
  // segments a calculation asks from one point at once (a patch's five sample points, a cell
  // row), which an implementation may trace together. The answers are visible()'s.
  virtual void visible_from(const Vec3& from, std::span<const Vec3> to, bool* seen) const {
    for (size_t i = 0; i < to.size(); ++i) seen[i] = visible(from, to[i]);
  }
  static constexpr size_t kMaxSegmentsFrom = 16;
  // `visible` or `hidden` only when visible() says so for every segment from a point of `a` to a
  // point of `b` (each element a point, segment or planar polygon by its corners, its convex
  // hull; geometry/shaft.h); `partial` when unknown. The default knows nothing.
  virtual Shaft classify(std::span<const Vec3> /*a*/, std::span<const Vec3> /*b*/) const {
    return Shaft::partial;
  }
  // classify(a, b) for a shaft inside one whose classification left the faces `among` (a part of
  // an element already classified; a ShaftFaces{} when none was: every face), and when the
  // verdict is `partial`, the faces still undecided into `undecided`. The default does not
  // narrow.
  virtual Shaft classify_within(std::span<const Vec3> a, std::span<const Vec3> b,
                                const ShaftFaces& /*among*/, ShaftFaces& undecided) const {
    undecided = ShaftFaces{};
    return classify(a, b);
  }
  // visible(from, to) for a segment of a shaft whose classify_within left `faces`: the same
  // answer, from those faces alone. The default traces the segment.
  virtual bool visible_among(const Vec3& from, const Vec3& to, const ShaftFaces& /*faces*/) const {
    return visible(from, to);
  }
};

// True when `visibility` is set and says the segment is blocked (null: nothing blocks).
inline bool blocked(const Visibility* visibility, const Vec3& from, const Vec3& to) {
  return visibility && !visibility->visible(from, to);
}

// An exact test behind a cheap filter: only segments that meet one of `boxes` go to `exact`;
// every other segment is visible. Exact (not an approximation) when every face that can block a
// segment of interest lies inside some box: in a convex room only obstacles can block a segment
// between two of its points, so their boxes are the filter (calc/indirect).
class BoxFilteredVisibility final : public Visibility {
 public:
  BoxFilteredVisibility(const Visibility& exact, std::vector<Box3> boxes)
      : exact_(exact), boxes_(std::move(boxes)) {}
  bool visible(const Vec3& from, const Vec3& to) const override {
    for (const Box3& box : boxes_)
      if (segment_meets_box(from, to, box)) return exact_.visible(from, to);
    return true;
  }
  // The segments that meet a box go to the exact test together.
  void visible_from(const Vec3& from, std::span<const Vec3> to, bool* seen) const override {
    if (to.size() > kMaxSegmentsFrom) return Visibility::visible_from(from, to, seen);
    Vec3 exact_to[kMaxSegmentsFrom];
    bool exact_seen[kMaxSegmentsFrom];
    size_t index[kMaxSegmentsFrom], m = 0;
    for (size_t i = 0; i < to.size(); ++i) {
      seen[i] = true;
      for (const Box3& box : boxes_)
        if (segment_meets_box(from, to[i], box)) {
          index[m] = i, exact_to[m++] = to[i];
          break;
        }
    }
    if (m == 0) return;
    exact_.visible_from(from, std::span<const Vec3>(exact_to, m), exact_seen);
    for (size_t k = 0; k < m; ++k) seen[index[k]] = exact_seen[k];
  }
  // Every segment the exact test passes, this one passes too; a hidden one may miss the boxes.
  Shaft classify(std::span<const Vec3> a, std::span<const Vec3> b) const override {
    return exact_.classify(a, b) == Shaft::visible ? Shaft::visible : Shaft::partial;
  }

 private:
  const Visibility& exact_;
  std::vector<Box3> boxes_;
};

}  // namespace luxgrid::geometry
