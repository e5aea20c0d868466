#pragma once
// The occlusion test for the segments of one shaft whose classification left a few faces
// undecided (Visibility::classify_within, ShaftFaces): every other face provably crosses none of
// them, so each segment asks only those faces (Visibility::visible_among), a few plane tests
// instead of a trace through the scene, and gets the same answer. Callers must ask only segments
// of that shaft (calc/indirect: the sample points of a partly hidden patch, or its cells, from the
// point its verdict was asked for).
#include <span>

#include "geometry/visibility.h"

namespace luxgrid::geometry {

class NarrowedVisibility final : public Visibility {
 public:
  // `faces` must be narrowed (ShaftFaces::narrowed()); `exact` outlives this object.
  NarrowedVisibility(const Visibility& exact, const ShaftFaces& faces)
      : exact_(exact), faces_(faces) {}
  bool visible(const Vec3& from, const Vec3& to) const override {
    return exact_.visible_among(from, to, faces_);
  }
  Shaft classify(std::span<const Vec3> a, std::span<const Vec3> b) const override {
    return exact_.classify(a, b);
  }

 private:
  const Visibility& exact_;
  ShaftFaces faces_;
};

}  // namespace luxgrid::geometry
