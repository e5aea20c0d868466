#pragma once
// The scene's visibility test (geometry/visibility.h): Intel Embree 3's occlusion query over the
// triangles of a set of faces, built once, queried from many threads. Embree only proposes the
// faces a segment may cross; geometry/face_crossing.h's rule decides each in double, so grazing
// configurations (a segment through an L's reflex corner, along the ceiling) get the rule's
// answer, not rounding's. No Embree in this header (pimpl; the implementation is
// geometry/embree/occlusion.cpp, in the luxgrid_geometry_embree library).
#include <memory>
#include <vector>

#include "geometry/room.h"
#include "geometry/visibility.h"

namespace luxgrid::geometry {

// A hit closer than this to either end of the segment does not count. Luminaires sit on
// ceilings and grid points sit on floors, walls and obstacle tops: without the allowance the
// face a point lies on would hide it from every light. 1 um is far below any modelled
// dimension (a 2 mm wall is 2000 times thicker) and far above double rounding at 1 km
// (~1e-13 m).
inline constexpr double kOcclusionEndAllowance_m = 1e-6;

class OcclusionTree final : public Visibility {
 public:
  explicit OcclusionTree(const std::vector<Face>& faces);
  ~OcclusionTree() override;
  OcclusionTree(const OcclusionTree&) = delete;
  OcclusionTree& operator=(const OcclusionTree&) = delete;

  // True when no face crosses the segment from `a` to `b` by geometry/face_crossing.h's rule
  // (shortened by kOcclusionEndAllowance_m at both ends, grazing faces and edges by its rule).
  // Thread-safe (const, the scene is built in the constructor).
  bool visible(const Vec3& a, const Vec3& b) const override;
  // The same for several segments from one point, traced as one coherent stream (Embree's
  // rtcOccluded1M), with the same answers.
  void visible_from(const Vec3& a, std::span<const Vec3> b, bool* seen) const override;
  // geometry/shaft.h's verdict over the same faces.
  Shaft classify(std::span<const Vec3> a, std::span<const Vec3> b) const override;
  // The same, narrowed (geometry/visibility.h): the faces left are the classifier's.
  Shaft classify_within(std::span<const Vec3> a, std::span<const Vec3> b, const ShaftFaces& among,
                        ShaftFaces& undecided) const override;
  // visible(from, to) from the faces left alone: each decided by the same rule
  // (geometry/face_crossing.h) on the same segment as the trace's candidates are, so the same
  // answer, since every face the trace could accept is among them.
  bool visible_among(const Vec3& from, const Vec3& to, const ShaftFaces& faces) const override;

  size_t triangle_count() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace luxgrid::geometry
