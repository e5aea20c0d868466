#pragma once
// An aperture's triangles (aperture_integral.h) cut along the planes through the receiver point
// and given edges: where an exterior obstruction's edge crosses the view through an opening, the
// integrand jumps (sky on one side, the obstruction's face on the other), and the aperture rule's
// error estimate would see the jump only by chance. Cut along every such plane, each piece sees
// one thing throughout, and the rule converges on it as on a smooth integrand.
#include <array>
#include <vector>

#include "calc/daylight/aperture_integral.h"

namespace luxgrid::daylight {

// `triangles` cut by the plane through `point` and each edge of `edges` that lies at least in
// part on the side of the plane through `beyond_origin` with normal `beyond_normal` (the outer
// side of the opening's plane: edges wholly inside cannot be seen through the opening); each
// piece convex and fanned into triangles. An edge in line with the point is skipped (its plane
// is undefined and its view a line).
std::vector<Triangle3> split_along_edges(const std::vector<Triangle3>& triangles, const Vec3& point,
                                         const std::vector<std::array<Vec3, 2>>& edges,
                                         const Vec3& beyond_origin, const Vec3& beyond_normal);

}  // namespace luxgrid::daylight
