#pragma once
// The triangles of scene.glb's objects (report/scene_glb.h), in luxgrid's coordinates (metres,
// +z up): rooms seen from inside, obstacles from outside, a luminaire's opening, body and C0
// arrow in its own frame, markers, photometric solids, grid surfaces. Each triangle is
// counter-clockwise seen from the side it shows.
#include <vector>

#include "calc/scene.h"
#include "geometry/surface_grid.h"
#include "report/gltf_writer.h"
#include "report/photometric_solid.h"

namespace luxgrid::report {

// A room's floor (facing up), walls and ceiling (facing the room): three primitives, in that
// order, without materials. Triangles facing inward, so that from outside the walls and ceiling
// between the eye and the room are not drawn and the room is seen into. `openings` (those of
// this room) are holes in the faces they lie in (geometry/polygon_with_holes.h); a face without
// one is drawn as without openings.
std::vector<gltf::Primitive> room_primitives(
    const calc::Room& room, const std::vector<calc::DaylightOpening>& openings = {});

// A daylight opening (window, roof light): its pane, the polygon as triangles (to be drawn from
// both sides), and its outline, a closed line through its corners.
gltf::Primitive daylight_pane_primitive(const calc::Room& room,
                                        const calc::DaylightOpening& opening);
gltf::Primitive daylight_outline_primitive(const calc::DaylightOpening& opening);
// An obstacle's prism, faces outward.
gltf::Primitive prism_primitive(const geometry::Obstacle& obstacle);

// In the luminaire's frame (C0 along +x, nadir -z; photometry/intensity_distribution.h): the
// luminous opening at z = 0 facing down, at its real size and shape (a point opening as a disk of
// kPointOpeningDiameter); a box on it (the body, kBodyHeight tall); a flat arrow from the centre
// along +x just below the opening (the C0 marker).
inline constexpr double kPointOpeningDiameter = 0.03;  // m
inline constexpr double kBodyHeight = 0.04;            // m
gltf::Primitive opening_primitive(const photometry::LuminousOpening& opening);
gltf::Primitive body_primitive(const photometry::LuminousOpening& opening);
gltf::Primitive c0_arrow_primitive(const photometry::LuminousOpening& opening);

// An octahedron of `radius` about the origin: the marker of a point or an observer's eye.
gltf::Primitive marker_primitive(double radius);

// The solid in the luminaire's frame: the sample in direction d at distance I(d) x m_per_cd.
gltf::Primitive solid_primitive(const PhotometricSolid& solid, double m_per_cd);

// A grid surface: a vertex at each active point (in order), moved kGridLift along its normal so
// that a grid on a floor or wall is not hidden in it; two triangles per cell whose four points are
// active, one where three are, facing the way the grid's normals point. A grid of more than
// kMaxGridSide points along a side is drawn with every k-th row or column and the last (k the
// least that gives at most kMaxGridSide + 1), so that a million-point grid makes a scene of a
// megabyte, not of a hundred: the 3D view is an overview, the map and the CSV hold every point.
// `vertex_of` gets each point's vertex index (-1: inactive or not drawn).
inline constexpr double kGridLift = 0.005;  // m
inline constexpr int kMaxGridSide = 120;
gltf::Primitive grid_primitive(const geometry::SurfaceGrid& grid, std::vector<int>* vertex_of);

}  // namespace luxgrid::report
