#include "geometry/polygon_with_holes.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

namespace luxgrid::geometry {

namespace {
// Exact predicates on the doubles given: the triangulation's vertices are the corners themselves,
// so the triangles cover the region without a gap or a sliver from rounding. Constructions are
// needed only where two edges cross (Exact_predicates_tag), which valid input does not have.
using HolesKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
// A vertex's index into HoledTriangulation::vertices; -1 until it has one.
struct HolesVertexIndex {
  int i = -1;
};
using HolesVertexBase = CGAL::Triangulation_vertex_base_with_info_2<HolesVertexIndex, HolesKernel>;
using HolesFaceBase = CGAL::Constrained_triangulation_face_base_2<HolesKernel>;
using HolesTds = CGAL::Triangulation_data_structure_2<HolesVertexBase, HolesFaceBase>;
using HolesCdt =
    CGAL::Constrained_Delaunay_triangulation_2<HolesKernel, HolesTds, CGAL::Exact_predicates_tag>;

// Inside `poly` strictly (the boundary counts as outside): a triangle's centroid lies a third of
// its smallest height away from its edges, and no constraint crosses a triangle, so the centroid
// is inside a region exactly when the triangle is.
bool strictly_inside(const Vec2& p, const Polygon2& poly) {
  return locate(p, poly, 0.0) == Location::inside;
}
}  // namespace

HoledTriangulation triangulate_with_holes(const Polygon2& outline,
                                          const std::vector<Polygon2>& holes) {
  HoledTriangulation out;
  HolesCdt cdt;
  std::vector<const Polygon2*> rings = {&outline};
  for (const Polygon2& h : holes) rings.push_back(&h);
  for (const Polygon2* ring : rings) {
    std::vector<HolesCdt::Vertex_handle> corners;
    for (const Vec2& c : *ring) {
      const auto v = cdt.insert(HolesCdt::Point(c.x, c.y));
      if (v->info().i < 0) v->info().i = static_cast<int>(out.vertices.size());  // else met before
      out.vertices.push_back(c);
      corners.push_back(v);
    }
    for (std::size_t k = 0; k < corners.size(); ++k) {
      const auto a = corners[k], b = corners[(k + 1) % corners.size()];
      if (a != b) cdt.insert_constraint(a, b);
    }
  }
  // Points the triangulation made where constraints cross: numbered after the corners.
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    if (v->info().i >= 0) continue;
    v->info().i = static_cast<int>(out.vertices.size());
    out.vertices.emplace_back(v->point().x(), v->point().y());
  }
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const std::array<int, 3> t = {f->vertex(0)->info().i, f->vertex(1)->info().i,
                                  f->vertex(2)->info().i};
    const Vec2 centroid = (out.vertices[t[0]] + out.vertices[t[1]] + out.vertices[t[2]]) / 3.0;
    if (!strictly_inside(centroid, outline)) continue;
    bool in_hole = false;
    for (const Polygon2& h : holes) in_hole = in_hole || strictly_inside(centroid, h);
    if (!in_hole) out.triangles.push_back(t);  // CGAL's faces are counter-clockwise
  }
  return out;
}

}  // namespace luxgrid::geometry
