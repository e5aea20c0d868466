#pragma once
// The sun's direction in the scene: from its altitude and azimuth (given, or computed for a
// site and a local time by solar_position.h), with the plan's north. Convention
// (docs/daylight.md): +z up, +y north when the north angle is 0; azimuths clockwise from true
// north (east 90 degrees); the north angle is the direction of true north in the plan, clockwise
// from +y.
#include "util/robust_math.h"

namespace luxgrid::daylight {

struct Site {
  double latitude_deg = 0.0;     // north positive
  double longitude_deg = 0.0;    // east positive
  double timezone_h = 0.0;       // local standard time minus UTC, hours
  double north_angle_deg = 0.0;  // true north in the plan, clockwise from +y
  double elevation_m = 0.0;
};

struct LocalTime {
  int year = 2000, month = 1, day = 1, hour = 12, minute = 0;
  double second = 0.0;
};

struct SunPosition {
  double altitude_deg = 0.0;  // above the horizon, refraction included
  double azimuth_deg = 0.0;   // clockwise from true north
};

// The unit vector toward the sun in the scene frame.
Vec3 sun_direction(const SunPosition& sun, double north_angle_deg);

// The sun's position at a site at a local standard time [Reda2008].
SunPosition sun_at(const Site& site, const LocalTime& time);

}  // namespace luxgrid::daylight
