#include "calc/daylight/solar_position.h"

#include <cmath>

#include "calc/daylight/spa_terms.h"
#include "util/robust_math.h"

namespace luxgrid::daylight {
namespace {

double wrap_degrees(double x) {
  const double r = std::fmod(x, 360.0);
  return r < 0.0 ? r + 360.0 : r;
}
double sin_d(double x) { return std::sin(x * kDegToRad); }
double cos_d(double x) { return std::cos(x * kDegToRad); }

// [Reda2008, Eq. 4]: the Julian day of a UT date and fraction of day, Gregorian calendar.
double julian_day(int year, int month, double day) {
  if (month < 3) year -= 1, month += 12;
  double jd =
      std::floor(365.25 * (year + 4716.0)) + std::floor(30.6001 * (month + 1)) + day - 1524.5;
  if (jd > 2299160.0) {
    const double a = std::floor(year / 100.0);
    jd += 2.0 - a + std::floor(a / 4.0);
  }
  return jd;
}

template <size_t N>
double periodic_sum(const std::array<spa::PeriodicTerm, N>& terms, double jme) {
  double sum = 0.0;
  for (const spa::PeriodicTerm& t : terms) sum += t.A * std::cos(t.B + t.C * jme);
  return sum;
}

// A polynomial in x from its coefficients, lowest first.
template <size_t N>
double polynomial(const std::array<double, N>& c, double x) {
  double y = 0.0;
  for (size_t i = N; i-- > 0;) y = y * x + c[i];
  return y;
}

}  // namespace

SpaResult solar_position(const SpaInput& in) {
  SpaResult out;
  // 3.1: time scales.
  const double day_fraction =
      in.day +
      (in.hour - in.timezone_h + (in.minute + (in.second + in.delta_ut1_s) / 60.0) / 60.0) / 24.0;
  const double jd = julian_day(in.year, in.month, day_fraction);
  const double jde = jd + in.delta_t_s / 86400.0;
  const double jc = (jd - 2451545.0) / 36525.0, jce = (jde - 2451545.0) / 36525.0;
  const double jme = jce / 10.0;
  out.julian_day = jd;

  // 3.2: the Earth's heliocentric longitude, latitude and radius vector (Eq. 9-12).
  const std::array<double, 6> l{periodic_sum(spa::kL0, jme), periodic_sum(spa::kL1, jme),
                                periodic_sum(spa::kL2, jme), periodic_sum(spa::kL3, jme),
                                periodic_sum(spa::kL4, jme), periodic_sum(spa::kL5, jme)};
  const std::array<double, 2> b{periodic_sum(spa::kB0, jme), periodic_sum(spa::kB1, jme)};
  const std::array<double, 5> r{periodic_sum(spa::kR0, jme), periodic_sum(spa::kR1, jme),
                                periodic_sum(spa::kR2, jme), periodic_sum(spa::kR3, jme),
                                periodic_sum(spa::kR4, jme)};
  const double L = wrap_degrees(polynomial(l, jme) / 1e8 * kRadToDeg);
  const double B = polynomial(b, jme) / 1e8 * kRadToDeg;
  const double R = polynomial(r, jme) / 1e8;
  out.heliocentric_longitude_deg = L, out.heliocentric_latitude_deg = B, out.radius_au = R;

  // 3.3: geocentric longitude and latitude (Eq. 13-14).
  const double theta = wrap_degrees(L + 180.0), beta = -B;

  // 3.4: nutation in longitude and obliquity (Eq. 15-23).
  const std::array<double, 5> x{
      polynomial(std::array<double, 4>{297.85036, 445267.111480, -0.0019142, 1.0 / 189474.0}, jce),
      polynomial(std::array<double, 4>{357.52772, 35999.050340, -0.0001603, -1.0 / 300000.0}, jce),
      polynomial(std::array<double, 4>{134.96298, 477198.867398, 0.0086972, 1.0 / 56250.0}, jce),
      polynomial(std::array<double, 4>{93.27191, 483202.017538, -0.0036825, 1.0 / 327270.0}, jce),
      polynomial(std::array<double, 4>{125.04452, -1934.136261, 0.0020708, 1.0 / 450000.0}, jce)};
  double delta_psi = 0.0, delta_epsilon = 0.0;
  for (const spa::NutationTerm& t : spa::kNutation) {
    const double arg =
        (t.Y0 * x[0] + t.Y1 * x[1] + t.Y2 * x[2] + t.Y3 * x[3] + t.Y4 * x[4]) * kDegToRad;
    delta_psi += (t.a + t.b * jce) * std::sin(arg);
    delta_epsilon += (t.c + t.d * jce) * std::cos(arg);
  }
  delta_psi /= 36000000.0, delta_epsilon /= 36000000.0;
  out.nutation_longitude_deg = delta_psi, out.nutation_obliquity_deg = delta_epsilon;

  // 3.5: the true obliquity of the ecliptic (Eq. 24-25).
  const double u = jme / 10.0;
  const double epsilon0 =
      polynomial(std::array<double, 11>{84381.448, -4680.93, -1.55, 1999.25, -51.38, -249.67,
                                        -39.05, 7.12, 27.87, 5.79, 2.45},
                 u);
  const double epsilon = epsilon0 / 3600.0 + delta_epsilon;
  out.obliquity_deg = epsilon;

  // 3.6-3.8: aberration, the apparent sun longitude, the apparent sidereal time (Eq. 26-30).
  const double delta_tau = -20.4898 / (3600.0 * R);
  const double lambda = theta + delta_psi + delta_tau;
  out.apparent_longitude_deg = lambda;
  const double nu0 = wrap_degrees(280.46061837 + 360.98564736629 * (jd - 2451545.0) +
                                  0.000387933 * jc * jc - jc * jc * jc / 38710000.0);
  const double nu = nu0 + delta_psi * cos_d(epsilon);

  // 3.9-3.10: geocentric right ascension and declination (Eq. 31-32).
  const double alpha = wrap_degrees(
      std::atan2(sin_d(lambda) * cos_d(epsilon) - std::tan(beta * kDegToRad) * sin_d(epsilon),
                 cos_d(lambda)) *
      kRadToDeg);
  const double delta =
      safe_asin(sin_d(beta) * cos_d(epsilon) + cos_d(beta) * sin_d(epsilon) * sin_d(lambda)) *
      kRadToDeg;
  out.right_ascension_deg = alpha, out.declination_deg = delta;

  // 3.11: the observer's local hour angle (Eq. 33).
  const double H = wrap_degrees(nu + in.longitude_deg - alpha);
  out.hour_angle_deg = H;

  // 3.12: topocentric right ascension and declination: the parallax (Eq. 34-40).
  const double xi = 8.794 / (3600.0 * R);
  const double u_rad = std::atan(0.99664719 * std::tan(in.latitude_deg * kDegToRad));
  const double xx = std::cos(u_rad) + in.elevation_m / 6378140.0 * cos_d(in.latitude_deg);
  const double yy =
      0.99664719 * std::sin(u_rad) + in.elevation_m / 6378140.0 * sin_d(in.latitude_deg);
  const double delta_alpha =
      std::atan2(-xx * sin_d(xi) * sin_d(H), cos_d(delta) - xx * sin_d(xi) * cos_d(H)) * kRadToDeg;
  const double delta_prime = std::atan2((sin_d(delta) - yy * sin_d(xi)) * cos_d(delta_alpha),
                                        cos_d(delta) - xx * sin_d(xi) * cos_d(H)) *
                             kRadToDeg;

  // 3.13-3.14: topocentric hour angle and zenith angle with refraction (Eq. 41-44).
  const double H_prime = H - delta_alpha;
  const double e0 = safe_asin(sin_d(in.latitude_deg) * sin_d(delta_prime) +
                              cos_d(in.latitude_deg) * cos_d(delta_prime) * cos_d(H_prime)) *
                    kRadToDeg;
  double delta_e = 0.0;
  if (e0 >= -(0.26667 + in.refraction_at_sunrise_deg))
    delta_e = in.pressure_mbar / 1010.0 * 283.0 / (273.0 + in.temperature_c) * 1.02 /
              (60.0 * std::tan((e0 + 10.3 / (e0 + 5.11)) * kDegToRad));
  out.zenith_deg = 90.0 - (e0 + delta_e);

  // 3.15: topocentric azimuth, eastward from north (Eq. 45-46).
  const double gamma =
      std::atan2(sin_d(H_prime), cos_d(H_prime) * sin_d(in.latitude_deg) -
                                     std::tan(delta_prime * kDegToRad) * cos_d(in.latitude_deg)) *
      kRadToDeg;
  out.azimuth_deg = wrap_degrees(gamma + 180.0);
  return out;
}

}  // namespace luxgrid::daylight
