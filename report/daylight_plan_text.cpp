#include "report/daylight_plan_text.h"

#include "util/format.h"

namespace luxgrid::report {
namespace {

std::string sky_text(const calc::DaylightPlan& d) {
  if (d.sky == "uniform") return "uniform sky";
  if (d.sky == "cie-overcast") return "traditional CIE overcast sky";
  return "CIE standard general sky type " + d.sky;
}

std::string percent_text(double fraction) { return format_double("%.2g %%", 100.0 * fraction); }

// Why the internally reflected component is 0.
std::string irc_skipped_text(const calc::DaylightPlan& d) {
  if (!d.reflecting_surfaces) return "no room surface reflects";
  if (d.indirect_off) return "settings.indirect is \"off\"";
  return "no openings";
}

std::string lm_text(double lm) { return format_double("%.4g", lm) + " lm"; }

}  // namespace

std::string daylight_summary(const calc::Plan& plan) {
  const calc::DaylightPlan& d = *plan.daylight;
  std::string out =
      "daylight: " + sky_text(d) + ", E_h " + format_double("%.6g", d.diffuse_horizontal_lx) +
      " lx, " + std::to_string(d.openings) + " openings; sky component " +
      (d.sky_exact ? "exact" : "adaptive") + ", externally reflected " +
      (d.ground_exact ? "exact" : "adaptive") + ", internally reflected " +
      (d.internally_reflected && plan.indirect_run
           ? "by " + std::to_string(plan.indirect_run->patches) + " patches of " +
                 format_double("%.3g", plan.indirect_run->patch_size_m) + " m, " +
                 (plan.indirect_run->bounces_asked == 0
                      ? "converged"
                      : std::to_string(plan.indirect_run->bounces_asked) + " bounce(s)")
           : std::string("0 (") + irc_skipped_text(d) + ")") +
      "; visibility: " + (plan.visibility.on ? "on" : "off");
  return out;
}

std::vector<std::string> daylight_notes(const calc::Plan& plan) {
  const calc::DaylightPlan& d = *plan.daylight;
  std::vector<std::string> notes;
  std::string sky = "daylight: " + sky_text(d);
  if (d.has_sun)
    sky += ", sun at " + format_double("%.4g", d.sun_altitude_deg) + " deg altitude, " +
           format_double("%.5g", d.sun_azimuth_deg) + " deg azimuth" +
           (d.sun_from_site ? " (NREL SPA for the site and local time)" : "");
  sky += "; E_h / L_z = " + format_double("%.10g", d.sky_integral_sr) + " sr (quadrature error " +
         format_double("%.1e", d.sky_integral_error_sr) + " sr); ground reflectance " +
         format_double("%.3g", d.ground_reflectance);
  notes.push_back(sky);
  const auto method = [&](bool exact, double error_percent) {
    return exact ? std::string("exact (Lambert's formula over each opening)")
                 : "adaptive to " + percent_text(d.relative_tolerance / 2.0) +
                       " of each point's value, largest error estimate " +
                       format_double("%.2g", error_percent) + " % of E_h";
  };
  notes.push_back("daylight: sky component " + method(d.sky_exact, d.sky_error_percent));
  notes.push_back("daylight: externally reflected component (ground" +
                  std::string(d.exterior_obstructions > 0 ? " and exterior obstructions" : "") +
                  ") " + method(d.ground_exact, d.ground_error_percent));
  if (d.exterior_obstructions > 0)
    notes.push_back(
        "daylight: " + std::to_string(d.exterior_obstructions) +
        " exterior obstructions hide the sky and the ground behind them; each face is seen "
        "instead with the luminance rho / pi x the illuminance on it from the unobstructed sky "
        "and ground (uniform over the face; the building, the other obstructions and "
        "reflections between them neglected), counted in the externally reflected component; "
        "the views through the openings are cut along the obstructions' edges");
  if (d.internally_reflected)
    notes.push_back(
        "daylight: internally reflected component: the light entering through the openings (" +
        lm_text(d.flux_entering_lm) + (d.exterior_obstructions > 0 ? " as if unobstructed" : "") +
        ") lands on the rooms' surfaces (" + lm_text(d.flux_on_surfaces_lm) +
        ", each patch's share integrated by the sky and ground components' own integration) "
        "and is carried between them by the reflected light's interreflection, the openings "
        "holes in its mesh; " +
        lm_text(d.flux_escaping_lm) + " of the reflected light leave through the openings again");
  else
    notes.push_back("daylight: internally reflected component 0: " + irc_skipped_text(d));
  if (d.direct_sun) {
    notes.push_back(
        "daylight: direct sun on, " + format_double("%.6g", d.direct_normal_lx) +
        " lx normal to the sun: the sun a point direction, seen through an opening where the "
        "ray towards it crosses the opening and nothing in the room hides it, times the "
        "glazing's transmittance at its incidence and the opening's factors (sharp shadow "
        "edges, no penumbra); " +
        lm_text(d.sun_flux_entering_lm) +
        " enter through the openings; no part of DF, added to E (E_sun_direct, E_sun_reflected)");
    if (d.sun_reflected)
      notes.push_back("daylight: the sun's reflected light by a run of its own (" +
                      std::to_string(d.sun_patches) + " patches of " +
                      format_double("%.3g", d.sun_patch_size_m) +
                      " m), each patch's sunlit area the openings projected along the sun onto it" +
                      (d.sun_shadow_samples > 0
                           ? ", shadows inside the room sampled at " +
                                 std::to_string(d.sun_shadow_samples * d.sun_shadow_samples) +
                                 " points per sunlit triangle"
                           : std::string(" (exact: nothing in the room casts a shadow)")) +
                      "; " + lm_text(d.sun_flux_on_surfaces_lm) + " land on the surfaces, " +
                      lm_text(d.sun_flux_escaping_lm) + " of its reflected light leave again");
  }
  if (d.luminaires_left_out > 0)
    notes.push_back("daylight: " + std::to_string(d.luminaires_left_out) +
                    " luminaires left out (the daylight scene lights nothing electric)");
  return notes;
}

std::vector<std::string> daylight_warnings(const calc::Plan& plan) {
  const calc::DaylightPlan& d = *plan.daylight;
  std::vector<std::string> warnings;
  if (d.points_outside_rooms > 0)
    warnings.push_back("daylight: " + std::to_string(d.points_outside_rooms) +
                       " points lie in no room: their daylight is not calculated (0)");
  if (d.indirect_off && d.reflecting_surfaces)
    warnings.push_back(
        "daylight: settings.indirect is \"off\", so the internally reflected component is 0 and "
        "DF is SC + ERC only (an underestimate wherever the room's surfaces reflect light)");
  return warnings;
}

}  // namespace luxgrid::report
