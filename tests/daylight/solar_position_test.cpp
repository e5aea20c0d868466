// The NREL Solar Position Algorithm (calc/daylight/solar_position.h) against the paper's own
// worked example [Reda2008, Table A5.1]: Golden, Colorado, 17 October 2003, 12:30:30 local
// standard time (UTC - 7), latitude 39.742476, longitude -105.1786, elevation 1830.14 m,
// 820 mbar, 11 C, delta T 67 s. The paper prints each intermediate to the digits given here.
#include <gtest/gtest.h>

#include "calc/daylight/solar_position.h"
#include "calc/daylight/sun_direction.h"

namespace luxgrid::daylight {
namespace {

SpaInput golden_2003() {
  SpaInput in;
  in.year = 2003, in.month = 10, in.day = 17, in.hour = 12, in.minute = 30, in.second = 30;
  in.timezone_h = -7.0, in.delta_ut1_s = 0.0, in.delta_t_s = 67.0;
  in.longitude_deg = -105.1786, in.latitude_deg = 39.742476, in.elevation_m = 1830.14;
  in.pressure_mbar = 820.0, in.temperature_c = 11.0, in.refraction_at_sunrise_deg = 0.5667;
  return in;
}

TEST(SolarPosition, PublishedExample) {
  const SpaResult r = solar_position(golden_2003());
  EXPECT_NEAR(r.julian_day, 2452930.312847, 1e-6);
  EXPECT_NEAR(r.heliocentric_longitude_deg, 24.0182616917, 1e-10);
  EXPECT_NEAR(r.heliocentric_latitude_deg, -0.0001011219, 1e-10);
  EXPECT_NEAR(r.radius_au, 0.9965422974, 1e-10);
  EXPECT_NEAR(r.nutation_longitude_deg, -0.00399840, 1e-8);
  EXPECT_NEAR(r.nutation_obliquity_deg, 0.00166657, 1e-8);
  EXPECT_NEAR(r.obliquity_deg, 23.440465, 1e-6);
  EXPECT_NEAR(r.apparent_longitude_deg, 204.0085519281, 1e-10);
  EXPECT_NEAR(r.right_ascension_deg, 202.22741, 1e-5);
  EXPECT_NEAR(r.declination_deg, -9.31434, 1e-5);
  EXPECT_NEAR(r.hour_angle_deg, 11.105902, 1e-6);
  EXPECT_NEAR(r.zenith_deg, 50.11162, 1e-5);
  EXPECT_NEAR(r.azimuth_deg, 194.34024, 1e-5);
}

// A site's position goes through the same algorithm: the same instant gives the same sun to
// within what the defaults (delta T 69 s, 1010 mbar, 10 C) move it.
TEST(SolarPosition, SiteAndLocalTime) {
  Site site;
  site.latitude_deg = 39.742476, site.longitude_deg = -105.1786, site.timezone_h = -7.0;
  site.elevation_m = 1830.14;
  const SunPosition sun = sun_at(site, LocalTime{2003, 10, 17, 12, 30, 30.0});
  EXPECT_NEAR(sun.altitude_deg, 90.0 - 50.11162, 0.01);
  EXPECT_NEAR(sun.azimuth_deg, 194.34024, 0.01);
}

// Azimuth clockwise from north, +y north: due south at 60 degrees is (0, -1/2, sqrt(3)/2); a
// plan whose north points along +x (north angle 90) turns it to -x.
TEST(SolarPosition, SceneDirection) {
  const Vec3 south = sun_direction(SunPosition{60.0, 180.0}, 0.0);
  EXPECT_NEAR(south.x, 0.0, 1e-15);
  EXPECT_NEAR(south.y, -0.5, 1e-15);
  EXPECT_NEAR(south.z, std::sqrt(3.0) / 2.0, 1e-15);
  const Vec3 east = sun_direction(SunPosition{0.0, 90.0}, 0.0);
  EXPECT_NEAR(east.x, 1.0, 1e-15);
  const Vec3 turned = sun_direction(SunPosition{60.0, 180.0}, 90.0);
  EXPECT_NEAR(turned.x, -0.5, 1e-15);
  EXPECT_NEAR(turned.y, 0.0, 1e-15);
}

}  // namespace
}  // namespace luxgrid::daylight
