#pragma once
// Does light travel freely from a luminaire to a point? Walls of non-convex rooms, walls between
// rooms and obstacles block it. The scene's faces for geometry's occlusion test
// (geometry/occlusion.h, the geometry::Visibility that direct, indirect light and glare ask), built
// once per scene, queried from TBB workers, and the plan's decision whether the scene needs one. No
// CGAL here.
#include <memory>
#include <string>
#include <vector>

#include "calc/scene.h"
#include "geometry/occlusion.h"

namespace luxgrid::calc {

// The loader's Room as geometry sees it.
geometry::RoomShape room_shape(const Room& room);

// Every face of the scene: per room its floor, ceiling and walls (normals into the room), then
// its obstacles' faces (normals outward). Also the input for indirect light.
std::vector<geometry::Face> scene_faces(const Scene& scene);

// Why the scene needs an occlusion test, or why not: each thing that can block light, counted
// (report/plan_text.h words it: "on: 2 obstacles, non-convex room 'L'").
struct VisibilityDecision {
  bool on = false;
  bool no_rooms = false;  // off: no rooms and no obstacles
  size_t obstacles = 0;
  size_t rooms = 0;  // more than one room counts
  std::vector<std::string> non_convex_rooms;
  size_t luminaires_outside = 0;              // outside every room
  size_t openings_reaching = 0;               // reaching outside their room
  std::string first_outside, first_reaching;  // the first such luminaire's label
  size_t points_outside = 0;                  // active surface points outside every room
};

// The scene's occlusion test over scene_faces: visible(from, to) is true when nothing lies between;
// hits within geometry::kOcclusionEndAllowance_m (1 um) of either end are ignored, so a luminaire
// on the ceiling and a point on a floor, wall or obstacle top see each other. nullptr when nothing
// can block light: at most one room, convex, no obstacles, every luminaire and every active surface
// point inside it (or no rooms and no obstacles at all). `decision` is set for the plan either way.
std::unique_ptr<geometry::OcclusionTree> make_visibility(const Scene& scene,
                                                         VisibilityDecision& decision);

// True when `p` lies in the closed volume of `room`, within `tolerance_m`. Points this close
// outside a room still count as inside: luminaires are placed on ceilings and grid points on
// walls, and their coordinates carry rounding. The default is the occlusion test's end
// allowance (1 um), so "inside" here and "not blocked" there agree.
bool inside_room(const Room& room, const Vec3& p,
                 double tolerance_m = geometry::kOcclusionEndAllowance_m);

}  // namespace luxgrid::calc
