#pragma once
// Which luminaires can light which points. Rooms are closed: walls, floor and ceiling block
// light, and a room has no openings (doors, windows) yet. So a luminaire lights the rooms its
// opening lies in or overlaps, and nothing else; a point inside a room needs only those
// luminaires, and only the faces near that room to test what blocks them. This makes direct
// light O(points x luminaires that can reach them) instead of O(points x all luminaires), and
// keeps each visibility query in a tree of the room's own faces.
//
// The rule, per point (docs/architecture.md, "Direct light"):
// - inside one room (within 1 um of its closed volume: on its floor, walls or ceiling counts
//   as inside): the luminaires whose opening box touches that room's bounding box;
// - inside several rooms (on a wall two rooms share): the luminaires of each of them;
// - outside every room: every luminaire, each tested through the whole scene's visibility
//   tree, as before.
// Light does not pass through a room's boundary: a point on a wall gets no light from a
// luminaire in the room behind that wall unless the point lies in both rooms.
#include <cstdint>
#include <memory>
#include <vector>

#include "calc/scene.h"
#include "calc/scene_visibility.h"

namespace luxgrid::calc {

// Points that share the same rooms share the same luminaires and the same occlusion tree.
struct ReachZone {
  std::vector<uint32_t> luminaires;  // indices into Scene::luminaires, ascending
  std::shared_ptr<const geometry::Visibility>
      visibility;  // null when the plan has no visibility test
};

class DirectReach {
 public:
  // `visibility`: the plan's test over the whole scene (null: nothing can block light). With at
  // most one room every point reaches every luminaire and only one zone exists.
  DirectReach(const Scene& scene, std::shared_ptr<const geometry::Visibility> visibility);

  // The zone of every point of `grid` (same order as grid.points), adding zones for room sets
  // seen for the first time. Not thread-safe; call it before the parallel work.
  std::vector<uint32_t> zones_of(const geometry::SurfaceGrid& grid);

  const ReachZone& zone(uint32_t id) const { return zones_[id]; }
  size_t zone_count() const { return zones_.size(); }

 private:
  uint32_t zone_for_rooms(const std::vector<uint32_t>& rooms);

  const Scene& scene_;
  std::shared_ptr<const geometry::Visibility> visibility_;
  std::vector<geometry::Face> faces_;  // the scene's, once the first room zone needs them
  bool per_room_ = false;
  std::vector<ReachZone> zones_;                   // zone 0: every luminaire, the whole tree
  std::vector<std::vector<uint32_t>> zone_rooms_;  // the room set of each zone (zone 0: none)
};

// The zones of one grid's points, for direct_illuminance (calc/direct.h).
struct GridReach {
  const DirectReach& reach;
  std::vector<uint32_t> zone_of_point;  // same order as the grid's points
};

}  // namespace luxgrid::calc
