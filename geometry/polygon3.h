#pragma once
// Planar polygons in space (patches, clipped openings): area vector, centroid, diameter and the
// half-space clip, on plain doubles (no CGAL), for code that runs per patch or per point. The
// flat outlines these come from are in polygon.h.
#include <vector>

#include "util/robust_math.h"

namespace luxgrid::geometry {

using Polygon3 = std::vector<Vec3>;

// Area vector of a planar polygon (Newell's method): |result| = area (m^2), direction = the
// normal of the side from which the corners run counter-clockwise.
Vec3 area_vector(const Polygon3& p);

// Area-weighted centroid of a planar polygon.
Vec3 polygon_centroid(const Polygon3& p);

// Largest distance between two corners (m).
double polygon_diameter(const Polygon3& p);

// `poly` clipped to the half-space n . (y - origin) >= 0 (Sutherland-Hodgman; the horizon clip).
Polygon3 clip_to_half_space(const Polygon3& poly, const Vec3& origin, const Vec3& n);

}  // namespace luxgrid::geometry
