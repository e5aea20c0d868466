#pragma once
// The sun's topocentric position by NREL's Solar Position Algorithm [Reda2008]: the Earth's
// heliocentric position from the VSOP87 periodic terms (spa_terms.h), nutation, aberration,
// the observer's parallax and the atmospheric refraction; +-0.0003 degrees over the years -2000
// to 6000. Its steps and symbols follow the paper's section 3.
namespace luxgrid::daylight {

struct SpaInput {
  int year = 2000, month = 1, day = 1;  // Gregorian calendar date
  int hour = 12, minute = 0;            // local standard time
  double second = 0.0;
  double timezone_h = 0.0;                    // local standard time minus UTC, hours (Denver: -7)
  double delta_ut1_s = 0.0;                   // UT1 - UTC, s
  double delta_t_s = 69.0;                    // TT - UT1, s (about 69 s in the 2020s)
  double longitude_deg = 0.0;                 // east positive
  double latitude_deg = 0.0;                  // north positive
  double elevation_m = 0.0;                   // above sea level
  double pressure_mbar = 1010.0;              // annual mean local pressure
  double temperature_c = 10.0;                // annual mean local temperature
  double refraction_at_sunrise_deg = 0.5667;  // the paper's atmos_refract
};

struct SpaResult {
  double julian_day = 0.0;
  double heliocentric_longitude_deg = 0.0;  // L
  double heliocentric_latitude_deg = 0.0;   // B
  double radius_au = 0.0;                   // R
  double nutation_longitude_deg = 0.0;      // delta psi
  double nutation_obliquity_deg = 0.0;      // delta epsilon
  double obliquity_deg = 0.0;               // epsilon
  double apparent_longitude_deg = 0.0;      // lambda
  double right_ascension_deg = 0.0;         // alpha (geocentric)
  double declination_deg = 0.0;             // delta (geocentric)
  double hour_angle_deg = 0.0;              // H (observer local)
  double zenith_deg = 0.0;                  // topocentric, refraction included
  double azimuth_deg = 0.0;                 // topocentric, clockwise from north
  double elevation_deg() const { return 90.0 - zenith_deg; }
};

SpaResult solar_position(const SpaInput& in);

}  // namespace luxgrid::daylight
