#pragma once
// Exterior obstructions (docs/daylight.md, "Exterior obstructions"): axis-aligned boxes outside
// every room, such as neighbouring buildings, overhangs and fins, and the one query every light
// from outside asks of them: does an outward ray meet one, and which face first. The daylight
// integration (calc/daylight_light) asks it for each direction through an opening; a ray towards
// the sun must ask the same.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "util/robust_math.h"

namespace luxgrid::calc {

struct ExteriorObstruction {
  std::string name;
  Vec3 min{0.0}, max{0.0};   // the box's corners (m), min < max on every axis
  double reflectance = 0.0;  // of every face, diffuse
};

// A box's faces, numbered 2 axis + (1 for the +axis side): -x, +x, -y, +y, -z, +z.
constexpr int kBoxFaces = 6;
Vec3 box_face_normal(int face);  // the outward unit normal

struct ObstructionHit {
  std::size_t obstruction = 0;  // index into the list given
  int face = 0;                 // box_face_normal's numbering: the face the ray enters by
  double distance_m = 0.0;      // from the ray's origin
};

// The first obstruction the ray origin + t dir (t >= 0, dir a unit vector) enters, and by which
// face; none when it meets none. A ray starting on a box's face and leaving it meets that box
// only if it enters its interior. The slab test [KayKajiya1986]; ties between boxes go to the
// lower index.
std::optional<ObstructionHit> first_exterior_obstruction(
    const std::vector<ExteriorObstruction>& obstructions, const Vec3& origin, const Vec3& dir);

// The edges (pairs of corners) of the faces of `box` that face `point` (the point lies on the
// outer side of their planes): the only edges along which what a ray from `point` meets of this
// box can change.
std::vector<std::array<Vec3, 2>> edges_facing(const ExteriorObstruction& box, const Vec3& point);

}  // namespace luxgrid::calc
