#pragma once
// The luminous opening: from what a file says to luxgrid's LuminousOpening, and from that to the
// emitter polygon the near-field models integrate over.
#include <string>
#include <vector>

#include "photometry/photometry.h"

namespace luxgrid::photometry {

// IES LM-63 dimensions in metres (already converted from feet), as written: width along the
// C90-C270 axis (y), length along C0-C180 (x), height vertical. Signs select the shape
// (LM-63-2002 Table 1; LM-63-2019 Table 1 adds the same for horizontal cylinders):
//   0 0 0 point | w l > 0, h = 0 rectangle | w l h > 0 rectangle with luminous sides
//   w = l < 0, h = 0 circle | w != l < 0 ellipse | w l < 0, h > 0 vertical cylinder
//   w l h < 0 sphere / spheroid | w < 0, l > 0, h < 0 horizontal cylinder along C0
//   w > 0, l < 0, h < 0 horizontal cylinder along C90
// and the rule of LM-63-1986..1995: a negative width with length 0 is round, diameter |width|.
// Any other sign combination is not defined by LM-63: `warning` then says what was assumed.
LuminousOpening ies_opening(double width_m, double length_m, double height_m, std::string& warning);

// EULUMDAT luminous area (lines 16-21), in metres: length along C0, width along C90 (0 means
// circular with diameter = length), height = the largest of the four C-plane heights.
LuminousOpening eulumdat_opening(double length_m, double width_m, double height_m);

// The emitter polygon in luminaire coordinates, in the z = 0 plane: a rectangle (4 vertices) or
// an N-gon inscribed in the disk/ellipse (N = disk_segments, at least 3); empty for a point.
// Winding: counter-clockwise seen from below (from -z, where the light goes), so the right-hand
// normal (v1 - v0) x (v2 - v1) is -z, the direction of emission. Vertex 0 is on the +x side.
std::vector<Vec3> opening_polygon(const LuminousOpening& opening, int disk_segments = 32);

// Area of the opening itself (not of the polygon): l*w, or pi/4 l w for a disk; 0 for a point.
double opening_area_m2(const LuminousOpening& opening);

// Area of the opening projected on a plane perpendicular to `direction` (a unit vector from the
// luminaire outward, luminaire frame), m^2: the flat opening emits towards -z, so it counts
// area x max(0, -direction.z); luminous sides (height > 0) add their vertical faces as seen from
// the direction: a rectangle's two facing sides, length x height x |y| + width x height x |x|; a
// disk's (elliptic) cylinder, height x 2 sqrt((length/2)^2 y^2 + (width/2)^2 x^2). Spheres and
// horizontal cylinders are taken as the vertical box or cylinder of the same extent. 0 for a
// point and for a flat opening seen from behind.
double projected_area_m2(const LuminousOpening& opening, const Vec3& direction);

}  // namespace luxgrid::photometry
