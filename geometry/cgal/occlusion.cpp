#include "geometry/occlusion.h"

#include <list>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace luxgrid::geometry {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Triangle = K::Triangle_3;
using Iterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<K, Iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

K::Point_3 cgal(const Vec3& p) { return {p.x, p.y, p.z}; }
}  // namespace

struct OcclusionTree::Impl {
  std::vector<Triangle> triangles;  // the tree points into this: never resized after building
  Tree tree;
};

OcclusionTree::OcclusionTree(const std::vector<Face>& faces) : impl_(std::make_unique<Impl>()) {
  for (const auto& f : faces) {
    for (const auto& t : triangulate_face(f)) {
      Triangle tri(cgal(t[0]), cgal(t[1]), cgal(t[2]));
      if (!tri.is_degenerate()) impl_->triangles.push_back(tri);
    }
  }
  impl_->tree.insert(impl_->triangles.begin(), impl_->triangles.end());
  // CGAL builds lazily on the first query, which would race between TBB workers: build now.
  impl_->tree.build();
}

OcclusionTree::~OcclusionTree() = default;

bool OcclusionTree::visible(const Vec3& a, const Vec3& b) const {
  if (impl_->triangles.empty()) return true;
  const Vec3 d = b - a;
  const double len = glm::length(d);
  if (!(len > 2.0 * kOcclusionEndAllowance_m)) return true;  // the ends touch: nothing between
  const Vec3 step = d * (kOcclusionEndAllowance_m / len);
  const K::Segment_3 seg(cgal(a + step), cgal(b - step));
  return !impl_->tree.do_intersect(seg);
}

size_t OcclusionTree::triangle_count() const { return impl_->triangles.size(); }

}  // namespace luxgrid::geometry
