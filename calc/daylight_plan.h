#pragma once
// What the daylight scene did (docs/daylight.md), as values for the plan: the sky and its
// normalisation, how each component was integrated over the openings and the largest error
// estimate each reached, whether the internally reflected component was computed and its flux
// balance. report/plan_json and plan_text write it.
#include <cstddef>
#include <string>

namespace luxgrid::calc {

struct DaylightPlan {
  std::string sky;  // "1".."15", "cie-overcast", "uniform"
  double diffuse_horizontal_lx = 0.0;
  double ground_reflectance = 0.0;
  bool has_sun = false;  // the sun shapes a general sky; none for the uniform and overcast skies
  double sun_altitude_deg = 0.0, sun_azimuth_deg = 0.0;  // azimuth clockwise from true north
  bool sun_from_site = false;
  // E_h / L_z of the sky (sr) and its quadrature's error estimate
  // (calc/daylight/sky_normalisation).
  double sky_integral_sr = 0.0;
  double sky_integral_error_sr = 0.0;
  std::size_t openings = 0, glazed_openings = 0;
  // Exterior obstructions (daylight.obstructions): each hides the sky and the ground behind it
  // and is seen instead, its faces' luminance rho / pi times the illuminance on them from the
  // unobstructed sky and ground, in the externally reflected component; the views through the
  // openings are cut along their edges and integrated adaptively (docs/daylight.md).
  std::size_t exterior_obstructions = 0;
  // The sky and externally reflected components: exact (Lambert's formula: an unglazed opening,
  // nothing inside the room that can hide it, the uniform sky for the sky component) or adaptive
  // (calc/daylight/aperture_integral) to `relative_tolerance` of each point's value.
  bool sky_exact = false, ground_exact = false;
  double relative_tolerance = 0.0;
  // The largest error estimate over all points, in percent of E_h (daylight-factor points), of
  // each component, and the integrand's evaluations in all.
  double sky_error_percent = 0.0, ground_error_percent = 0.0;
  std::size_t evaluations = 0;
  std::size_t points_outside_rooms = 0;  // active points in no room: no daylight computed (0)
  // The internally reflected component: computed (the plan's indirect run, estimates and notes
  // say how) unless no room face or obstacle reflects or settings.indirect is "off" (IRC 0).
  bool internally_reflected = false;
  bool reflecting_surfaces = false;  // a room face or obstacle reflects
  bool indirect_off = false;         // settings.indirect "off"
  // Its balance (lm): the flux entering through the openings (DaylightLight::entering_flux_lm),
  // the part of it landing on the rooms' surfaces straight away (the first bounce; the rest
  // leaves through another opening, or is the first bounce's quadrature error), and the
  // reflected light leaving through the openings. What the surfaces absorb is the rest.
  double flux_entering_lm = 0.0, flux_on_surfaces_lm = 0.0, flux_escaping_lm = 0.0;
  std::size_t luminaires_left_out = 0;  // the daylight scene lights nothing electric
  // Direct sunlight (daylight.sun.direct_normal_lx; calc/daylight_sun.h), no part of DF: its
  // direct normal illuminance (lx), the shadow samples per side of each sunlit patch part (0:
  // no occlusion test, the sunlit areas exact), the flux entering through the openings, and
  // when it is reflected (as the sky's: sun_reflected) its own run's patches, the part landing
  // on the surfaces straight away and the reflected part leaving through the openings (lm).
  bool direct_sun = false, sun_reflected = false;
  double direct_normal_lx = 0.0;
  int sun_shadow_samples = 0;
  double sun_flux_entering_lm = 0.0, sun_flux_on_surfaces_lm = 0.0, sun_flux_escaping_lm = 0.0;
  std::size_t sun_patches = 0;
  double sun_patch_size_m = 0.0;
};

}  // namespace luxgrid::calc
