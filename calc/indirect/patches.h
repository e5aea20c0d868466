#pragma once
// The patch mesh of calc/indirect: every room face (floor, ceiling, one wall per outline edge)
// cut into convex planar patches of about `patch_size_m`. Patches are the unit of the radiosity
// solve and, after the first bounce, its virtual point lights ([Gadia2024]).
//
// The mesh is built here from Scene::rooms, with the faces and orientations of geometry/room.h
// (room_faces, obstacle_faces): walls are gridded rectangles; floor and ceiling are a grid over the
// outline's bounding box whose cells lie wholly inside the outline, plus the pieces of boundary
// cells clipped by the outline's ear-clipping triangles, so the patches tile the faces exactly for
// any simple outline. Obstacles (Room::obstacles) add their sides (gridded rectangles, normals
// outward), their top unless it touches the ceiling and their bottom unless it stands on the floor;
// the footprint of an obstacle standing on the floor (hanging from the ceiling) is cut out of the
// floor (ceiling), so no patch lies hidden under it and the room plus obstacle surfaces stay a
// closed, non-overlapping tiling (the first bounce's solid angles then still sum to 4 pi).
//
// Openings (Scene::openings: windows, roof lights; docs/daylight.md) are holes: light reaching an
// opening leaves the room, so no patch covers one. Each opening's triangles are cut out of the
// pieces of its face like an obstacle's footprint out of the floor, and every patch records the
// form factor from its centroid to the openings of its room (PatchMesh::escape_fraction), the
// share of its light that leaves: the transfer's renormalisation (radiosity.h, clustered.h)
// scales each source to 1 minus it instead of 1. A room without openings is meshed as before.
#include <array>
#include <string>
#include <vector>

#include "calc/scene.h"
#include "geometry/polygon.h"
#include "geometry/polygon3.h"
#include "geometry/visibility.h"

namespace luxgrid::calc::indirect {

using geometry::Polygon2;
using geometry::Polygon3;

enum class FaceKind { floor, ceiling, wall, obstacle };

struct Patch {
  Polygon3 polygon;  // convex, counter-clockwise seen from the room side
  Vec3 centroid{0.0};
  Vec3 normal{0.0};  // unit, into the room (obstacles: out of the obstacle, into the room)
  double area_m2 = 0.0;
  double diameter_m = 0.0;
  double reflectance = 0.0;
  int room = 0;  // index into Scene::rooms
  FaceKind face = FaceKind::floor;
  int face_index = 0;  // 0 for floor / ceiling; outline edge index for a wall; obstacle index in
                       // Room::obstacles for an obstacle face
  // Parallelograms (wall patches, whole floor and ceiling cells, obstacle sides: nearly all) are
  // also seen as 2 x 2 quarters, each of a quarter of the area and half the diameter, with these
  // centroids: the point kernel on the quarters is as accurate at half the distance as on the
  // whole patch (form_factor.h, quarter_kernel_form_factor).
  bool has_quarters = false;
  std::array<Vec3, 4> quarter_centroid{};
};

struct PatchMesh {
  std::vector<Patch> patches;
  // patches of room r are [room_begin[r], room_begin[r + 1]).
  std::vector<size_t> room_begin;
  double patch_size_m = 0.0;  // the size actually used (after the budget)
  // Per patch: the form factor from its centroid to the openings of its room (Lambert's formula
  // on each opening polygon, form_factor.h; no visibility test: exact in a convex room without
  // obstacles), the fraction of its light that leaves the room. Empty when the scene has no
  // openings (every room closed).
  std::vector<double> escape_fraction;
  // The renormalisation target of patch `i`'s transfer: 1 minus its escape fraction.
  double kept_fraction(size_t i) const {
    return escape_fraction.empty() ? 1.0 : 1.0 - escape_fraction[i];
  }
};

// Patch mesh of all rooms at `patch_size_m`. Throws InputError naming the room for an outline
// with fewer than 3 vertices, a non-positive height, an outline that crosses itself (the room
// leaks), or a reflectance outside [0, 1] (room faces or an obstacle, named).
PatchMesh build_patch_mesh(const Scene& scene, double patch_size_m);

// `mesh` with each patch marked in `split` (parallelograms only: Patch::has_quarters; others are
// kept) replaced by its four quarters, in its place, so every room's patches stay together and
// keep tiling its faces; the escape fractions are those of the new patches. split_mask.h says
// which to cut.
PatchMesh split_patches(const Scene& scene, const PatchMesh& mesh, const std::vector<char>& split);

// Total surface area of a room's faces (floor + ceiling + walls), m^2, without obstacles.
double room_surface_area(const Room& room);

// True when the room's outline is convex (then no face can hide another from a point inside).
bool outline_is_convex(const Room& room);

// Index of the room containing `p` (outline, floor to ceiling, within `tolerance_m` of the
// boundary), or -1.
int room_containing(const Scene& scene, const Vec3& p, double tolerance_m = 1e-3);

// Indices of all rooms containing `p` (as room_containing): more than one only on a wall, floor
// or ceiling two rooms share.
std::vector<int> rooms_containing(const Scene& scene, const Vec3& p, double tolerance_m);

// Fraction of `target` visible from `from`: its centroid and the midpoints between centroid and
// each vertex, each lifted off the patch by `lift_m` along its normal (so the patch's own face
// does not hide them). 1 when `visibility` is null.
double visible_fraction(const geometry::Visibility* visibility, const Vec3& from,
                        const Patch& target, double lift_m);

// visible_fraction(visibility, from, target, lift_m), the same number, where every segment lies in
// a shaft whose classification left the faces `among` undecided (Visibility::classify_within):
// where they are narrowed, each segment asks only them (geometry/narrowed_visibility.h), a few
// plane tests instead of a trace through the scene, and gets the occlusion test's answer.
// Otherwise the segments are traced as there.
double visible_fraction_within(const geometry::Visibility* visibility, const Vec3& from,
                               const Patch& target, double lift_m,
                               const geometry::ShaftFaces& among);

}  // namespace luxgrid::calc::indirect
