#pragma once
// The occlusion test's rule for one face (geometry/occlusion.h): does the segment from `a` to `b`
// pass through it? Decided in double from the face's own polygon, so the answer does not depend on
// the ray tracer that found the face as a candidate, its float arithmetic or its traversal order.
//
// Configurations of measure zero (a segment touching an edge, or lying in a face's plane) are
// common in practice: grid points, patch centres and luminaires on regular grids line up with an
// L's reflex corner or run in the ceiling's plane. The rule decides them, not rounding:
// - The segment's ends may lie on a face: it counts from kOcclusionEndAllowance_m (1 um) after `a`
//   to as much before `b` (luminaires on ceilings, grid points on floors, walls, obstacle tops).
// - Only a transversal crossing counts: a segment whose shortened ends are on the same side of
//   the face's plane, or that stays within kGrazing_m (1 nm) of the plane, is not blocked by it
//   (light grazing a surface reaches).
// - A room's face (floor, ceiling, wall) is a sheet, shrunk by kGrazing_m: a segment crossing
//   its plane within 1 nm of its boundary grazes the edge and is not blocked by it (light grazing
//   a non-convex room's reflex corner reaches).
// - An obstacle is a closed solid, each face grown by kGrazing_m: a segment crossing a face's
//   plane within 1 nm of its boundary is blocked, so a segment that enters a box exactly through
//   one edge and leaves through another is blocked (as the solid blocks it), and one lying in the
//   plane of a face is caught by the neighbouring faces it crosses at their edge.
#include <vector>

#include "geometry/polygon.h"
#include "geometry/room.h"

namespace luxgrid::geometry {

// Touching, for the rule: a segment this close to a face's plane, or crossing it this close to its
// boundary. Far above double rounding at 1 km (~1e-13 m), so configurations that line up exactly
// are decided by the rule; far below any modelled dimension and below the 1 um end allowance, so
// shadow edges stay where they were (tests/calc/scene_visibility_test.cpp pins one to 1 um).
inline constexpr double kGrazing_m = 1e-9;

// A face in its own plane: `outline` in the orthonormal frame (u, v) about `origin`.
struct FaceSheet {
  Vec3 origin{0.0}, u{1, 0, 0}, v{0, 1, 0}, normal{0, 0, 1};
  Polygon2 outline;
  bool solid = false;                     // an obstacle's face: grown, not shrunk, at its boundary
  Vec2 outline_lo{0.0}, outline_hi{0.0};  // the outline's box in the face's frame, m
  bool rectangle = false;                 // the outline is that box (4 corners, edges along u, v)
};

FaceSheet face_sheet(const Face& face);

// True when the segment from `a` to `b` crosses `face` by the rule above.
bool segment_crosses(const FaceSheet& face, const Vec3& a, const Vec3& b);

// The segment from `a` to `b` as the rule reads it (its direction, and the end allowance's step
// along it), computed once for a segment asked of several faces (Visibility::visible_among):
// segment_crosses(face, shortened_segment(a, b)) is segment_crosses(face, a, b), the same
// arithmetic.
struct ShortenedSegment {
  Vec3 a{0.0}, b{0.0}, d{0.0}, step{0.0};
  bool touches = true;  // the ends within twice the allowance: nothing between
};
ShortenedSegment shortened_segment(const Vec3& a, const Vec3& b);
bool segment_crosses(const FaceSheet& face, const ShortenedSegment& s);

}  // namespace luxgrid::geometry
