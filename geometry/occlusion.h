#pragma once
// The scene's visibility test (geometry/visibility.h): a CGAL AABB tree of the triangles of a set
// of faces, built once, queried from many threads. No CGAL in this header (pimpl; the
// implementation is geometry/cgal/occlusion.cpp, in the luxgrid_geometry_cgal library).
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

  // True when no face crosses the open segment from `a` to `b`, shortened by
  // kOcclusionEndAllowance_m at both ends. Thread-safe (const, the tree is built in the
  // constructor).
  bool visible(const Vec3& a, const Vec3& b) const override;

  size_t triangle_count() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace luxgrid::geometry
