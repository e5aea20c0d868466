#pragma once
// Vertical prisms (a footprint swept from z0 to z1: rooms and obstacles) that meet, and the union
// of obstacles that overlap. No CGAL in this header (the implementation, geometry/cgal/
// prism_union.cpp, uses CGAL's exact kernel and 2D Boolean operations).
//
// Why: each obstacle is meshed into faces of its own, and every face reflects. The same box given
// twice puts two faces in each place, each reflecting the light it receives, so the room gets
// light twice; faces of one obstacle inside another, or two faces pressed together, receive and
// re-emit light no real surface would. The union of the obstacles is the solid the user means,
// and its faces are the only ones that can see the room.
#include <cstddef>
#include <optional>
#include <vector>

#include "geometry/polygon.h"
#include "geometry/room.h"

namespace luxgrid::geometry {

// How two prisms meet, exactly (CGAL's exact predicates and constructions).
enum class PrismContact {
  apart,       // no common volume and no common face area (touching along an edge or at a corner)
  share_face,  // no common volume, but faces pressed together over some area
  overlap,     // common volume
};

PrismContact prism_contact(const Polygon2& a, double a_z0, double a_z1, const Polygon2& b,
                           double b_z0, double b_z1);

// The obstacles of one room with the overlapping ones (common volume or pressed-together faces,
// through any chain of such pairs) replaced by their union, when that union is again one prism:
// - all of the group have the same footprint (as point sets) and z ranges that join into one
//   interval (a box given twice, boxes stacked on the same footprint): that footprint, the
//   joined z range;
// - or all have the same z0 and z1 and their footprints join into one polygon without a hole
//   (overlapping boxes, a desk pushed against another): that polygon (CGAL's join, collinear
//   corners removed), those z0 and z1.
// The members must also share one reflectance (the union has one). The union keeps the place and
// name of its first member; obstacles that meet nothing are kept unchanged (byte for byte).
struct ObstacleUnion {
  std::vector<Obstacle> obstacles;
  // Per obstacle of `obstacles`: the indices of the input obstacles it stands for, first the one
  // whose name it keeps.
  std::vector<std::vector<std::size_t>> members;
  // A group whose union is no prism (different heights overlapping, different reflectances, a
  // ring enclosing a hole): the first two of its members that meet, and how. `obstacles` and
  // `members` are then empty.
  struct Conflict {
    std::size_t first = 0, second = 0;
    PrismContact contact = PrismContact::overlap;
  };
  std::optional<Conflict> conflict;
};

ObstacleUnion unite_obstacles(const std::vector<Obstacle>& obstacles);

}  // namespace luxgrid::geometry
