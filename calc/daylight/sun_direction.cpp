#include "calc/daylight/sun_direction.h"

#include <cmath>

#include "calc/daylight/solar_position.h"

namespace luxgrid::daylight {

Vec3 sun_direction(const SunPosition& sun, double north_angle_deg) {
  const double altitude = sun.altitude_deg * kDegToRad;
  const double plan_azimuth = (sun.azimuth_deg + north_angle_deg) * kDegToRad;  // from +y
  const double horizontal = std::cos(altitude);
  return Vec3{horizontal * std::sin(plan_azimuth), horizontal * std::cos(plan_azimuth),
              std::sin(altitude)};
}

SunPosition sun_at(const Site& site, const LocalTime& time) {
  SpaInput in;
  in.year = time.year, in.month = time.month, in.day = time.day;
  in.hour = time.hour, in.minute = time.minute, in.second = time.second;
  in.timezone_h = site.timezone_h;
  in.latitude_deg = site.latitude_deg, in.longitude_deg = site.longitude_deg;
  in.elevation_m = site.elevation_m;
  const SpaResult r = solar_position(in);
  return {r.elevation_deg(), r.azimuth_deg};
}

}  // namespace luxgrid::daylight
