#include "report/daylight_section_html.h"

#include <cstdio>

#include "calc/statistics.h"
#include "geometry/polygon3.h"
#include "report/colour_scale.h"
#include "report/false_colour.h"
#include "report/html_report.h"
#include "report/html_text.h"
#include "util/format.h"

namespace luxgrid::report {

namespace {

std::string sky_words(const std::string& sky) {
  if (sky == "uniform") return "uniform sky";
  if (sky == "cie-overcast") return "CIE traditional overcast sky (Moon and Spencer)";
  return "CIE standard general sky type " + sky;
}

std::string daylight_row(const std::string& key, const std::string& th, const std::string& td) {
  return "<tr data-daylight=\"" + key + "\"><th>" + th + "</th><td>" + td + "</td></tr>";
}

// The sky, the sun and the site, from the plan's daylight part (what the calculation used) and
// the scene's site.
std::string sky_table(const calc::DaylightPlan& d, const calc::Scene* scene) {
  std::string h = "<table class=\"daylight-sky\">";
  h += daylight_row("sky", "Sky", html_escape(sky_words(d.sky)));
  h += daylight_row("diffuse_horizontal_lx", "Diffuse horizontal illuminance E<sub>h</sub>",
                    format_double("%.0f", d.diffuse_horizontal_lx) + " lx");
  h += daylight_row("ground_reflectance", "Ground reflectance",
                    format_double("%.2f", d.ground_reflectance));
  if (d.has_sun) {
    h += daylight_row("sun_altitude_deg", "Sun altitude",
                      format_double("%.1f", d.sun_altitude_deg) + "&deg;");
    h += daylight_row("sun_azimuth_deg", "Sun azimuth",
                      format_double("%.1f", d.sun_azimuth_deg) +
                          "&deg; <span class=\"muted\">clockwise from true north</span>");
  }
  if (d.direct_sun)
    h += daylight_row("direct_normal_lx", "Direct sun",
                      format_double("%.0f", d.direct_normal_lx) +
                          " lx normal to the sun <span class=\"muted\">through the openings, "
                          "in E (E<sub>sun</sub>), not in DF</span>");
  const calc::DaylightInputs* in = scene && scene->daylight ? &*scene->daylight : nullptr;
  if (in && in->sun_from_site) {
    const daylight::Site& s = in->site;
    const daylight::LocalTime& t = in->local_time;
    char when[64];
    std::snprintf(when, sizeof when, "%04d-%02d-%02d %02d:%02d", t.year, t.month, t.day, t.hour,
                  t.minute);
    h += daylight_row("site", "Site",
                      "latitude " + format_double("%.4f", s.latitude_deg) + "&deg;, longitude " +
                          format_double("%.4f", s.longitude_deg) + "&deg;, elevation " +
                          format_double("%.0f", s.elevation_m) + " m");
    h += daylight_row("local_time", "Local standard time",
                      std::string(when) + " (UTC" + format_double("%+g", s.timezone_h) +
                          " h); the sun's position computed for it (NREL SPA)");
  }
  if (in && in->site.north_angle_deg != 0.0)
    h += daylight_row(
        "north_angle_deg", "North angle",
        format_double("%.1f", in->site.north_angle_deg) +
            "&deg; <span class=\"muted\">true north in the plan, clockwise from +y</span>");
  return h + "</table>\n";
}

std::string openings_table(const calc::Scene& scene) {
  std::string h =
      "<table class=\"daylight-openings\"><tr><th>Opening</th><th>Room</th><th>Face</th>"
      "<th class=\"num\">Area</th><th class=\"num\">Glazing transmittance</th>"
      "<th class=\"num\">Frame factor</th><th class=\"num\">Maintenance factor</th></tr>";
  for (const auto& o : scene.openings) {
    const std::string face = o.face.kind == calc::RoomFaceRef::Kind::floor ? "floor"
                             : o.face.kind == calc::RoomFaceRef::Kind::ceiling
                                 ? "ceiling"
                                 : "wall " + std::to_string(o.face.wall);
    h += "<tr data-opening=\"" + html_escape(o.name) + "\"><td>" + html_escape(o.name) +
         "</td><td>" + html_escape(scene.rooms.at(o.room).name) + "</td><td>" + face +
         "</td><td class=\"num\" data-value=\"area_m2\">" +
         format_double("%.2f", glm::length(geometry::area_vector(o.polygon))) +
         " m&sup2;</td><td class=\"num\" data-value=\"transmittance\">" +
         (o.glazing_transmittance ? format_double("%.2f", *o.glazing_transmittance)
                                  : std::string("unglazed")) +
         "</td><td class=\"num\" data-value=\"frame_factor\">" +
         format_double("%.2f", o.frame_factor) +
         "</td><td class=\"num\" data-value=\"maintenance_factor\">" +
         format_double("%.2f", o.maintenance_factor) + "</td></tr>";
  }
  return h + "</table>\n";
}

// The daylight factor as a result of its own (E = DF, its statistics), for the map.
calc::SurfaceResult daylight_factor_result(const calc::SurfaceResult& s) {
  calc::SurfaceResult df;
  df.grid = s.grid;
  df.E = s.DF;
  df.stats = calc::compute_statistics(df.E, s.grid.active);
  return df;
}

}  // namespace

std::string daylight_section_html(const calc::Results& results, const calc::Scene* scene) {
  if (results.scene != calc::LightingScene::daylight) return "";
  std::string h = "<section class=\"daylight\" id=\"daylight\">\n<h2>Daylight</h2>\n";
  if (results.plan.daylight) h += sky_table(*results.plan.daylight, scene);
  if (scene && !scene->openings.empty()) {
    h += "<h3>Openings</h3>\n" + openings_table(*scene);
    h += "<p class=\"caption\">Area: the opening's polygon. The light through an opening is "
         "scaled by its glazing's transmittance at each angle (clear glass, refractive index "
         "1.52), its frame factor and its maintenance factor. The plan views draw each opening "
         "in blue: a window as the part of its wall it takes, a roof light as its outline, "
         "dashed.</p>\n";
  }
  h += "<h3>Daylight factor</h3>\n<table class=\"daylight-factor\"><tr><th>Surface</th>"
       "<th class=\"num\">DF<sub>min</sub></th><th class=\"num\">DF<sub>avg</sub></th>"
       "<th class=\"num\">DF<sub>max</sub></th><th class=\"num\">DF<sub>min</sub> / "
       "DF<sub>avg</sub></th></tr>";
  std::vector<calc::SurfaceResult> maps;
  for (const auto& s : results.surfaces) {
    if (s.DF.size() != s.grid.points.size() || s.DF.empty()) continue;
    calc::SurfaceResult df = daylight_factor_result(s);
    h += "<tr data-surface=\"" + html_escape(s.grid.name) + "\"><td>" + html_escape(s.grid.name) +
         "</td><td class=\"num\" data-stat=\"DFmin\">" + format_double("%.2f", df.stats.Emin) +
         " %</td><td class=\"num\" data-stat=\"DFavg\">" + format_double("%.2f", df.stats.Eavg) +
         " %</td><td class=\"num\" data-stat=\"DFmax\">" + format_double("%.2f", df.stats.Emax) +
         " %</td><td class=\"num\">" + format_double("%.3f", df.stats.U0) + "</td></tr>";
    if (s.grid.kind == geometry::SurfaceGrid::Kind::grid) maps.push_back(std::move(df));
  }
  h += "</table>\n";
  // The maps: report/false_colour's plot of the daylight factor, its contour lines at
  // kDaylightFactorLevels instead of the legend's round values.
  PlotOverlay overlay;
  overlay.scene = scene;
  overlay.quantity = "DF";
  overlay.unit = "%";
  overlay.levels = kDaylightFactorLevels;
  for (const auto& df : maps) {
    const ColourScale scale = fit_scale(df.stats.Emin, df.stats.Emax);
    std::string png;
    write_false_colour_png(df, scale, {}, overlay, nullptr, nullptr, &png);
    std::string drawn;
    for (const PlotLevel& l : plot_levels(overlay, scale, df.stats.Emin, df.stats.Emax))
      drawn += (drawn.empty() ? "" : " ") + format_double("%g", l.value);
    h += "<figure class=\"df-map\" data-surface=\"" + html_escape(df.grid.name) +
         "\" data-df-levels=\"" + drawn + "\"><img alt=\"daylight factor of " +
         html_escape(df.grid.name) + "\" src=\"data:image/png;base64," + base64(png) +
         "\"><figcaption class=\"caption\">Daylight factor in % of the unobstructed sky's "
         "horizontal illuminance, smooth between the grid points; contour lines at 1, 2 and 5 % "
         "where the map reaches them.</figcaption></figure>\n";
  }
  return h + "</section>\n";
}

}  // namespace luxgrid::report
