#pragma once
// What a project gives for daylight: openings in room faces, and the sky, sun, site and ground
// (docs/daylight.md, docs/project-format.md). Built by project/project_daylight, read by the
// daylight calculation. SI units, scene frame (+z up).
#include <optional>
#include <string>
#include <vector>

#include "calc/daylight/en17037.h"
#include "calc/daylight/sky_luminance.h"
#include "calc/daylight/sun_direction.h"
#include "calc/exterior_obstructions.h"
#include "util/robust_math.h"

namespace luxgrid::calc {

// The face of a room an opening lies in.
struct RoomFaceRef {
  enum class Kind { floor, ceiling, wall };
  Kind kind = Kind::wall;
  std::size_t wall = 0;  // for a wall: the outline's edge from corner `wall` to `wall + 1`
};

// A window or roof light: a planar polygon in a face of a room (docs/daylight.md).
struct DaylightOpening {
  std::string name;
  std::size_t room = 0;       // index into Scene::rooms
  std::vector<Vec3> polygon;  // world coordinates, counter-clockwise seen from inside the room
  RoomFaceRef face;
  Vec3 inward_normal{0, 0, -1};  // the face's normal, into the room
  // Clear glass of this normal transmittance (calc/daylight/clear_glass.h); none: unglazed.
  std::optional<double> glazing_transmittance;
  double frame_factor = 1.0;        // the fraction of the opening not taken by the frame
  double maintenance_factor = 1.0;  // dirt on the glazing
};

// The sky and what shapes it.
struct DaylightInputs {
  daylight::SkyModel sky;                    // its sun set from `sun` (general skies)
  std::optional<daylight::SunPosition> sun;  // altitude, azimuth from true north
  daylight::Site site;                       // north angle; latitude etc. when the sun is computed
  bool sun_from_site = false;                // the sun was computed from site and local time
  daylight::LocalTime local_time;            // when sun_from_site
  // Direct sunlight through the openings (daylight.sun.direct_normal_lx): the sun's direct
  // normal illuminance, lx (calc/daylight_sun.h); none: no direct sun, only the sky.
  std::optional<double> direct_normal_lx;
  double diffuse_horizontal_lx = 10000.0;  // E_h of the unobstructed sky
  double ground_reflectance = 0.2;         // rho_g: the ground's luminance rho_g E_h / pi
  // Boxes outside every room (daylight.obstructions): they hide the sky and the ground behind
  // them and are seen instead (calc/exterior_obstructions.h).
  std::vector<ExteriorObstruction> obstructions;
  // EN 17037 daylight provision asked for (daylight.en17037): assessed on the daylight scene's
  // results (report/en17037_checks).
  std::optional<daylight::En17037Request> en17037;
};

}  // namespace luxgrid::calc
