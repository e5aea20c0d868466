#pragma once
// Triangles of a planar face with holes cut out of it: a room face with its windows and roof
// lights (docs/report.md, "scene.glb"). CGAL's constrained Delaunay triangulation behind a
// CGAL-free header (implemented in geometry/cgal/polygon_with_holes.cpp). A hole may touch the
// outline or another hole along an edge or at a corner, and may fill the outline (no triangle is
// left). Set-up code, not for the hot path.
#include <array>
#include <vector>

#include "geometry/polygon.h"

namespace luxgrid::geometry {

struct HoledTriangulation {
  // The outline's corners, then each hole's, in the order given (a corner given twice is kept
  // twice, the triangles use the first), then any point where two edges cross (none for holes
  // that lie inside the outline and do not overlap).
  std::vector<Vec2> vertices;
  // Indices into `vertices`, each triangle counter-clockwise.
  std::vector<std::array<int, 3>> triangles;
};

// The part of the simple counter-clockwise `outline` outside every hole (simple polygons of
// either orientation, inside the outline, not overlapping each other) as triangles whose union
// is that region exactly: their vertices are the given corners, so their areas add up to the
// outline's area less the holes' up to rounding.
HoledTriangulation triangulate_with_holes(const Polygon2& outline,
                                          const std::vector<Polygon2>& holes);

}  // namespace luxgrid::geometry
