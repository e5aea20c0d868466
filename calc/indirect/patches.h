#pragma once
// The patch mesh of calc/indirect: every room face (floor, ceiling, one wall per outline edge)
// cut into convex planar patches of about `patch_size_m`. Patches are the unit of the radiosity
// solve and, after the first bounce, its virtual point lights (ARCHITECTURE.md, seed 004).
//
// Until geometry/ delivers room faces and obstacles, the mesh is built here from Scene::rooms:
// walls are gridded rectangles; floor and ceiling are a grid over the outline's bounding box
// whose cells lie wholly inside the outline, plus the pieces of boundary cells clipped by the
// outline's ear-clipping triangles, so the patches tile the faces exactly for any simple outline.
#include <string>
#include <vector>

#include "calc/indirect/polygon.h"
#include "calc/scene.h"

namespace luxgrid::calc::indirect {

enum class FaceKind { floor, ceiling, wall };

struct Patch {
  Polygon3 polygon;   // convex, counter-clockwise seen from the room side
  Vec3 centroid{0.0};
  Vec3 normal{0.0};   // unit, into the room
  double area_m2 = 0.0;
  double diameter_m = 0.0;
  double reflectance = 0.0;
  int room = 0;       // index into Scene::rooms
  FaceKind face = FaceKind::floor;
  int face_index = 0; // 0 for floor / ceiling; outline edge index for a wall
};

struct PatchMesh {
  std::vector<Patch> patches;
  // patches of room r are [room_begin[r], room_begin[r + 1]).
  std::vector<size_t> room_begin;
  double patch_size_m = 0.0;  // the size actually used (after the budget)
};

// Patch mesh of all rooms at `patch_size_m`. Throws std::invalid_argument naming the room for an
// outline with fewer than 3 vertices or a non-positive height, or a reflectance outside [0, 1].
PatchMesh build_patch_mesh(const Scene& scene, double patch_size_m);

// Total surface area of a room's faces (floor + ceiling + walls), m^2.
double room_surface_area(const Room& room);

// True when the room's outline is convex (then no face can hide another from a point inside).
bool outline_is_convex(const Room& room);

// Index of the room containing `p` (outline, floor to ceiling, within `tolerance_m` of the
// boundary), or -1.
int room_containing(const Scene& scene, const Vec3& p, double tolerance_m = 1e-3);

}  // namespace luxgrid::calc::indirect
