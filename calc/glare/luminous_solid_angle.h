#pragma once
// The solid angle a luminaire's luminous area subtends at an eye, for eyes too near it for CIE
// 117's small-source omega = A_p / d^2 [CIE117]. That form grows without bound as the eye nears
// the opening (a 0.6 m panel 1 mm away would subtend 360 000 sr), while a surface seen from one
// side never subtends more than 2 pi sr. CIE 117 states UGR for sources of 3e-4 to 0.1 sr; above
// 0.1 sr luxgrid takes the exact solid angle (docs/glare.md), which A_p / d^2 overstates by
// about 2.5 % at 0.1 sr for a square seen on its axis, and by more the nearer the eye.
#include "photometry/photometry.h"
#include "util/robust_math.h"

namespace luxgrid::calc::glare {

// The largest solid angle of a source CIE 117 states UGR for [CIE117], sr.
inline constexpr double kLargestRatedSource_sr = 0.1;

// Corners of a disk or ellipse's polygon for the exact solid angle: the inscribed 256-gon has
// (1 - sin(2 pi / 256) 256 / (2 pi)) = 0.01 % less area than the disk.
inline constexpr int kSolidAngleDiskSegments = 256;

// Solid angle, sr, of the luminous surface of `opening` seen from `eye_local` (a position in the
// luminaire's frame, metres from the opening's centre): the flat opening (opening_polygon, in
// the plane z = 0, emitting towards -z) when the eye is below it, plus, for luminous sides
// (height > 0), each side face of the prism from z = 0 to z = height over that polygon whose
// front the eye sees. The faces of a convex body seen from outside do not overlap on the sphere,
// so their sum is the body's solid angle, at most 2 pi. Each face is a fan of triangles, each by
// Van Oosterom and Strackee's formula (geometry/spherical.h, [VanOosterom1983]). 0 for a point.
double luminous_solid_angle_sr(const photometry::LuminousOpening& opening, const Vec3& eye_local);

// Whether `eye_local` lies in the luminous surface's body: inside the prism (height > 0), or on
// the flat opening itself (within 1e-9 m of its plane, inside its polygon). An eye there sees no
// luminaire from outside, and no glare formula applies.
bool inside_luminous_opening(const photometry::LuminousOpening& opening, const Vec3& eye_local);

}  // namespace luxgrid::calc::glare
