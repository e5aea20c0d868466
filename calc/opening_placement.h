#pragma once
// Where an opening lies: the face of a room whose plane holds its polygon and whose outline
// contains it (docs/daylight.md). The project loader refuses an opening that lies in no face
// ("off its face"), that leaves the face it lies in ("crossing its edge"), or that overlaps
// another opening of the same face.
#include <string>
#include <vector>

#include "calc/daylight_inputs.h"
#include "calc/scene.h"

namespace luxgrid::calc {

// A point counts as in a face's plane within this distance: corners typed to the millimetre are
// in their plane; a wall of zero thickness has no other tolerance to give.
inline constexpr double kOpeningPlaneTolerance_m = 1e-6;

struct OpeningPlacement {
  bool found = false;
  RoomFaceRef face;
  Vec3 inward_normal{0, 0, 1};
  // Set when not found: why, for the message ("lies in no face of room \"office\"", "leaves wall
  // 0 of room \"office\" ...").
  std::string reason;
};

// The face of `room` that holds `polygon` (at least 3 corners). A polygon in a face's plane but
// not inside its outline is not found, with the reason that it crosses the face's edge.
OpeningPlacement place_opening(const Room& room, const std::vector<Vec3>& polygon);

// The opening's corners in its face's own 2D coordinates (x, y for floor and ceiling; the
// distance along the wall from its first corner and z for a wall), for overlap tests.
std::vector<Vec2> face_coordinates(const Room& room, const RoomFaceRef& face,
                                   const std::vector<Vec3>& polygon);

}  // namespace luxgrid::calc
