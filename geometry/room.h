#pragma once
// Rooms and obstacles as polygons and faces. geometry/ knows nothing of calc/: the project loader
// converts its Room into a RoomShape here. No CGAL in this header (CGAL lives in the .cpp files).
//
// Conventions (stated once, here):
// - An outline is the floor polygon seen from above, counter-clockwise, without a repeated
//   closing corner. Wall k runs from corner k to corner k+1 (wrapping); its label is "wall k".
// - Room faces have normals pointing INTO the room; obstacle faces have normals pointing OUT of
//   the obstacle (into the room around it). A face's corners run counter-clockwise seen from the
//   side its normal points to.
#include <string>
#include <vector>

#include "geometry/polygon.h"
#include "util/robust_math.h"

namespace luxgrid::geometry {

struct RoomShape {
  std::string name;
  Polygon2 outline;  // counter-clockwise (normalize_outline)
  double floor_z = 0.0;
  double height = 0.0;
  double floor_reflectance = 0.2;
  double wall_reflectance = 0.5;
  double ceiling_reflectance = 0.7;
};

// A box (optionally turned about z) or an extruded polygon: both are a footprint swept from z0
// to z1.
struct Obstacle {
  std::string name;
  Polygon2 footprint;  // counter-clockwise
  double z0 = 0.0, z1 = 0.0;
  double reflectance = 0.0;
};

struct Face {
  enum class Kind { floor, ceiling, wall, obstacle };
  Kind kind = Kind::wall;
  std::string label;          // `room "L" wall 3`, `obstacle "column" top`
  std::vector<Vec3> corners;  // planar, counter-clockwise seen from the normal's side
  Vec3 normal{0, 0, 1};       // unit
  double reflectance = 0.0;
};

// Checks a polygon and makes it counter-clockwise. `object` names it in messages, e.g.
// `room "L"`. Throws InputError("<object>: ...") for fewer than 3 corners, coincident neighbouring
// corners, zero area, or a polygon that crosses or touches itself (tested with CGAL's exact
// predicates). Returns true when the corners were clockwise and have been reversed: the caller
// turns that into a warning.
bool normalize_outline(Polygon2& outline, const std::string& object);

// Box from `min` to `max` turned by `rotation_z_rad` (counter-clockwise seen from above) about its
// own vertical centre line. Throws InputError(`obstacle "<name>": ...`) unless min < max in x, y
// and z.
Obstacle make_box(const std::string& name, const Vec3& min, const Vec3& max, double rotation_z_rad,
                  double reflectance);

// Prism: `outline` extruded from z0 to z1. Validates the outline like a room's (a clockwise
// outline is reversed; `reversed` tells the caller) and requires z0 < z1.
Obstacle make_prism(const std::string& name, Polygon2 outline, double z0, double z1,
                    double reflectance, bool* reversed = nullptr);

// Floor, ceiling and one wall per outline edge, normals into the room.
std::vector<Face> room_faces(const RoomShape& room);

// Sides, top and bottom of an obstacle, normals out of it.
std::vector<Face> obstacle_faces(const Obstacle& obstacle);

// The face's corners as triangles (ear clipping in the face's plane), for the AABB tree and
// for integration over faces.
std::vector<std::array<Vec3, 3>> triangulate_face(const Face& face);

double face_area(const Face& face);

}  // namespace luxgrid::geometry
