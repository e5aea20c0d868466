#include "report/html_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "geometry/polygon.h"
#include "report/compliance_table.h"
#include "report/daylight_section_html.h"
#include "report/embedded_scripts.h"
#include "report/en17037_html.h"
#include "report/energy.h"
#include "report/map_frame.h"
#include "report/observers_html.h"
#include "report/plan_text.h"
#include "report/plan_view_svg.h"
#include "report/png_file.h"
#include "report/polar_diagram.h"
#include "report/scene_view_html.h"
#include "util/format.h"

namespace luxgrid::report {

namespace {

// Grids up to this many points per side get their values printed as a table (EN 12464-1 asks for
// the grid values to be documented; beyond 30 x 30 a table no longer fits a printed page).
constexpr int kMaxValueTableSide = 30;

// A CSS string literal: quotes and backslashes escaped, '<' as an escape so "</style>" in a
// project name cannot end the style sheet.
std::string css_string(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    if (ch == '"' || ch == '\\')
      out += '\\', out += ch;
    else if (ch == '<')
      out += "\\3C ";
    else if (ch == '\n' || ch == '\r')
      out += ' ';
    else
      out += ch;
  }
  return out + "\"";
}

// Screen and print styles. Print: A4 with a running header (project name, report title) and a
// footer (date, "page N of M") in the page margins (CSS Paged Media margin boxes, which Chromium
// prints), the cover on a page of its own, no table or map split across pages.
std::string style(const std::string& project, const std::string& date) {
  std::string css = std::string("body { font-family: ") + kReportFontFamily +
                    R"(; font-size: 10pt; color: #111;
       max-width: 186mm; margin: 1.5em auto; padding: 0 1em; line-height: 1.35; }
h1 { font-size: 22pt; margin: .2em 0 .6em; } h2 { font-size: 14pt; border-bottom: 1.5px solid #333;
     margin-top: 1.4em; } h3 { font-size: 11.5pt; margin: 1em 0 .3em; }
table { border-collapse: collapse; margin: .4em 0; } td, th { border: 1px solid #bbb; padding: 2px 5px;
     text-align: left; vertical-align: top; } th { background: #eee; font-weight: 600; }
td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; }
table.values { font-size: 6.5pt; } table.values td { padding: 0 2px; text-align: right; border-color: #ddd; }
table.positions, table.types { width: 100%; font-size: 8pt; } table.positions td, table.types td { overflow-wrap: anywhere; }
table.meta th { width: 38mm; } .kicker { color: #555; font-size: 12pt; margin: 30mm 0 0; }
.met { color: #0a6b2f; font-weight: bold; } .notmet { color: #a10f0f; font-weight: bold; }
.notcalc { color: #8a5a00; font-weight: bold; } table.compliance { font-size: 9pt; } table.compliance td.num { white-space: nowrap; }
table.compliance td:last-child { overflow-wrap: anywhere; }
.surface { break-inside: avoid; page-break-inside: avoid; } .surface img, img.polar { max-width: 100%; height: auto; }
img.polar { width: 300px; } .plan { max-width: 100%; height: auto; } .luminaire-card { display: inline-block;
     margin: 0 1em 1em 0; vertical-align: top; break-inside: avoid; } .muted { color: #666; }
.keep { break-inside: avoid; } .caption { color: #444; font-size: 8.5pt; margin: .2em 0 .8em; } .method p { margin: .3em 0; }
@page { size: A4; margin: 18mm 13mm 16mm;
  @top-left { content: )" +
                    css_string(project) + R"(; font: 8pt sans-serif; color: #555; }
  @top-right { content: "Lighting calculation report"; font: 8pt sans-serif; color: #555; }
  @bottom-left { content: )" +
                    css_string(date) + R"(; font: 8pt sans-serif; color: #555; }
  @bottom-right { content: "Page " counter(page) " of " counter(pages); font: 8pt sans-serif; color: #555; } }
@media print { body { margin: 0; padding: 0; max-width: none; } h2 { break-after: avoid; }
  .cover { break-after: page; } h2.appendix { break-before: page; }
  .surface, .room, table.values, .luminaire-card, tr { break-inside: avoid; } a { color: inherit; } }
)" + scene_view_style();
  return css;
}

std::string stat_cell(const std::string& surface, const char* key, const std::string& text) {
  return "<td class=\"num\" data-surface=\"" + html_escape(surface) + "\" data-stat=\"" + key +
         "\">" + text + "</td>";
}

// The luminaire types (one row per photometry entry: the product as the file names it, count,
// flux and power) with their polar diagrams, then every luminaire's position.
std::string luminaire_sections(const std::vector<LuminaireType>& types, const calc::Scene& scene) {
  std::string h =
      "<h2>Luminaires</h2>\n<table class=\"types\"><tr><th>Type</th><th>Luminaire (from the "
      "file)</th>"
      "<th>Photometry file</th><th class=\"num\">Count</th><th class=\"num\">Flux each</th>"
      "<th class=\"num\">Power each</th><th class=\"num\">LOR</th>"
      "<th class=\"num\">UGR 4H&times;8H<br>crosswise / endwise</th></tr>";
  std::string cards;
  for (const LuminaireType& t : types) {
    const std::string& key = t.key;
    std::string product;
    if (!t.name.empty()) product += "<strong>" + html_escape(t.name) + "</strong>";
    if (!t.manufacturer.empty())
      product += (product.empty() ? "" : "<br>") + html_escape(t.manufacturer);
    if (!t.article.empty())
      product += (product.empty() ? "" : "<br>") + std::string("article ") + html_escape(t.article);
    if (product.empty())
      product = "<span class=\"muted\">" + html_escape(t.format) + ", no product data</span>";
    const std::string ugr = t.ugr_crosswise && t.ugr_endwise
                                ? format_double("%.1f", *t.ugr_crosswise) + " / " +
                                      format_double("%.1f", *t.ugr_endwise)
                                : std::string("&ndash;");
    h += "<tr data-type=\"" + html_escape(key) + "\"><td>" + html_escape(key) + "</td><td>" +
         product + "</td><td>" + html_escape(t.file) + "</td><td class=\"num\">" +
         std::to_string(t.count) + "</td><td class=\"num\">" +
         (t.flux_lm ? format_double("%.0f", *t.flux_lm) + " lm" : "&ndash;") +
         "</td><td class=\"num\" data-power=\"" + html_escape(key) + "\">" +
         (t.power_W ? format_double("%.1f", *t.power_W) + " W" : std::string("not in file")) +
         "</td><td class=\"num\">" +
         (t.lor ? format_double("%.2f", *t.lor) : std::string("&ndash;")) +
         "</td><td class=\"num\" data-ugr-table=\"" + html_escape(key) + "\">" + ugr + "</td></tr>";
    if (t.polar) {
      const Raster polar = polar_diagram(*t.polar, key, 600);
      cards += "<div class=\"luminaire-card\"><img class=\"polar\" alt=\"polar diagram of " +
               html_escape(key) + "\" src=\"data:image/png;base64," + base64(encode_png(polar)) +
               "\"></div>";
    }
  }
  h += "</table>\n<p class=\"caption\">Flux each: the luminaire's flux as used in the calculation "
       "(the file's, or the "
       "project's flux_lm). Power each: as the photometric file states it. LOR: light output "
       "ratio. UGR: the CIE 190 "
       "tabular value for a 4H &times; 8H room with reflectances 0.7 / 0.5 / 0.2, without "
       "maintenance factor.</p>\n" +
       cards + "\n";
  // Positions: the numbers are those of the plan view.
  h += "<h3>Positions</h3><table class=\"positions\"><tr><th "
       "class=\"num\">No.</th><th>Luminaire</th><th>Type</th>"
       "<th class=\"num\">x</th><th class=\"num\">y</th><th class=\"num\">z</th><th "
       "class=\"num\">Mounting height</th>"
       "<th class=\"num\">C0 towards</th><th class=\"num\">Tilt</th></tr>";
  for (size_t i = 0; i < scene.luminaires.size(); ++i) {
    const auto& l = scene.luminaires[i];
    const Vec3 p = l.pose.position;
    // Mounting height: above the floor of the room it hangs in (the first whose outline holds it).
    std::string mounting = "&ndash;";
    for (const auto& room : scene.rooms) {
      if (geometry::locate(Vec2(p), room.outline, 1e-6) != geometry::Location::outside) {
        mounting = format_double("%.2f", p.z - room.floor_z) + " m";
        break;
      }
    }
    const Vec3 c0 = l.pose.rotation * Vec3(1, 0, 0), aim = l.pose.rotation * Vec3(0, 0, -1);
    // C0's bearing in the plan, counter-clockwise from +x; the tilt is the aim's angle from
    // straight down.
    const double bearing = std::atan2(c0.y, c0.x) / kDegToRad;
    const double tilt = std::acos(std::clamp(-aim.z, -1.0, 1.0)) / kDegToRad;
    char row[512];
    std::snprintf(row, sizeof row,
                  "<tr data-luminaire=\"%zu\"><td class=\"num\">%zu</td><td>%s</td><td>%s</td><td "
                  "class=\"num\">%.2f</td>"
                  "<td class=\"num\">%.2f</td><td class=\"num\">%.2f</td><td "
                  "class=\"num\">%s</td><td class=\"num\">%.0f&deg;</td>"
                  "<td class=\"num\">%.0f&deg;</td></tr>",
                  i + 1, i + 1, html_escape(l.label).c_str(), html_escape(l.photometry).c_str(),
                  p.x, p.y, p.z, mounting.c_str(), std::abs(bearing) < 0.5 ? 0.0 : bearing, tilt);
    h += row;
  }
  h += "</table>\n<p class=\"caption\">x, y, z: the centre of the luminous opening in metres. "
       "Mounting height: above "
       "the room's floor. C0 towards: the direction of the luminaire's C0 plane in the plan, in "
       "degrees "
       "counter-clockwise from +x. Tilt: the angle between its axis and straight down.</p>\n";
  return h;
}

// One surface, appended to `h`: its map with what the picture shows, the statistics, its
// requirement rows, and for small grids the values themselves. The map's image goes to `put`
// as it is encoded, after the text before it.
void surface_section(const calc::SurfaceResult& s, const calc::Scene* scene, const ReportInput& in,
                     std::string& h, const TextSink& put) {
  const auto& g = s.grid;
  const bool grid = g.kind == geometry::SurfaceGrid::Kind::grid;
  h += "<div class=\"surface\" data-surface=\"" + html_escape(g.name) + "\"><h3>" +
       html_escape(g.name) + "</h3>\n";
  const auto png = in.png.find(g.name);
  if (png != in.png.end()) {
    h += "<img alt=\"false-colour illuminance of " + html_escape(g.name) +
         "\" src=\"data:image/png;base64,";
    put(h);
    h.clear();
    base64_to(png->second, put);
    h += "\">\n<p class=\"caption\">" + html_escape(map_frame(g, scene).description) +
         " Colours: maintained illuminance in lx (legend on the right), smooth between the grid "
         "points; white and "
         "black lines: isolux lines at the legend's values, the thick ones at a required value "
         "(marked red on the "
         "legend). Light grey: inside the room but outside the surface; mid grey: points left out "
         "(inside an "
         "obstacle).</p>\n";
  }
  h +=
      "<table><tr><th class=\"num\">Emin</th><th class=\"num\">Eavg</th><th class=\"num\">Emax</th>"
      "<th class=\"num\">U0</th><th class=\"num\">Ud</th><th>Points</th></tr><tr>";
  h += stat_cell(g.name, "Emin", format_lux_value(s.stats.Emin) + " lx");
  h += stat_cell(g.name, "Eavg", format_lux_value(s.stats.Eavg) + " lx");
  h += stat_cell(g.name, "Emax", format_lux_value(s.stats.Emax) + " lx");
  h += stat_cell(g.name, "U0", format_ratio_value(s.stats.U0));
  h += stat_cell(g.name, "Ud", format_ratio_value(s.stats.Ud));
  h += grid ? "<td>" + std::to_string(g.nu) + " x " + std::to_string(g.nv) + ", spacing " +
                  format_double("%.3f", g.spacing_u) + " x " + format_double("%.3f", g.spacing_v) +
                  " m</td>"
            : "<td>" + std::to_string(g.points.size()) + " points</td>";
  h += "</tr></table>\n";
  std::string rows;
  for (const auto& c : in.checks) {
    if (c.surface != g.name) continue;
    const std::string unit = requirement_unit(c.quantity);
    const char* f = c.quantity == "U0" || c.quantity == "modelling" ? "%.3f" : "%.1f";
    std::string required =
        std::string(c.upper_limit ? "&le; " : "&ge; ") + format_double(f, c.required) + unit;
    if (c.required_max)
      required = format_double(f, c.required) + " to " + format_double(f, *c.required_max);
    const char* cls = !c.calculated ? "notcalc" : c.met ? "met" : "notmet";
    rows += "<tr><td>" + html_escape(c.quantity) + "</td><td class=\"num\">" + required +
            "</td><td class=\"num\">" +
            (c.calculated ? format_double(f, c.achieved) + unit : std::string("&ndash;")) +
            "</td><td class=\"" + cls + "\">" + check_result(c) + "</td></tr>";
  }
  if (!rows.empty())
    h += "<table class=\"checks\"><tr><th>Requirement</th><th class=\"num\">Required</th><th "
         "class=\"num\">Achieved</th>"
         "<th>Result</th></tr>" +
         rows + "</table>\n";
  if (grid && g.nu <= kMaxValueTableSide && g.nv <= kMaxValueTableSide) {
    h += "<details open><summary>Values in lx (rows from the far edge, v, to the near edge; "
         "columns along u)</summary>"
         "<table class=\"values\">";
    for (int j = g.nv - 1; j >= 0; --j) {
      h += "<tr>";
      for (int i = 0; i < g.nu; ++i) {
        const size_t k = static_cast<size_t>(j) * g.nu + i;
        const bool on = k >= g.active.size() || g.active[k];
        h += "<td>" +
             (on && k < s.E.size() ? format_double("%.0f", s.E[k]) : std::string("&ndash;")) +
             "</td>";
      }
      h += "</tr>";
    }
    h += "</table></details>\n";
  } else if (g.kind == geometry::SurfaceGrid::Kind::observers) {
    h += observers_html(s);
  } else if (!grid) {
    h += "<table><tr><th>Point</th><th>Position (m)</th><th class=\"num\">E (lx)</th></tr>";
    for (size_t k = 0; k < g.points.size() && k < s.E.size(); ++k) {
      char buf[200];
      std::snprintf(buf, sizeof buf,
                    "<tr><td>P%zu</td><td>%.3f, %.3f, %.3f</td><td class=\"num\">%.1f</td></tr>",
                    k + 1, g.points[k].x, g.points[k].y, g.points[k].z, s.E[k]);
      h += buf;
    }
    h += "</table>\n";
  }
  h += "</div>\n";
}

// How the numbers were obtained, in words a client reads; the technical plan is in the appendix.
std::string method_section(const calc::Results& r, const calc::Scene* scene) {
  bool indirect = false, obstacles = false;
  for (const auto& s : r.surfaces)
    for (double e : s.E_indirect) indirect = indirect || e > 0.0;
  if (scene)
    for (const auto& room : scene->rooms) obstacles = obstacles || !room.obstacles.empty();
  std::string h = "<h2>How the values were calculated</h2>\n<div class=\"method\">";
  h += "<p><strong>Light straight from the luminaires.</strong> For every calculation point "
       "luxgrid adds up the light "
       "of each luminaire from its measured light distribution (the photometric file), its "
       "distance and the angle at "
       "which the light arrives. Where a point is close to a large luminaire, the luminaire is "
       "treated as a glowing "
       "surface rather than a point, so values right under a luminaire stay correct.</p>";
  if (obstacles)
    h += "<p><strong>Shadows.</strong> Obstacles in the rooms (columns, cabinets and the like) "
         "block the light that "
         "would pass through them.</p>";
  h += indirect ? "<p><strong>Light reflected by the room.</strong> Walls, floor, ceiling and "
                  "obstacles reflect part of "
                  "the light they receive, in proportion to their reflectance (see Rooms). luxgrid "
                  "divides them into "
                  "small patches and follows the light from patch to patch until further "
                  "reflections add nothing "
                  "measurable; every point then receives this reflected light as well.</p>"
                : "<p><strong>Light reflected by the room</strong> was <em>not</em> included in "
                  "this calculation: the "
                  "values are direct light only and lower than in the real room.</p>";
  if (scene) {
    h += "<p><strong>Maintenance.</strong> Luminaires and rooms get dirtier and lamps dimmer over "
         "time. Every "
         "illuminance in this report is the maintained value: the value of a new installation "
         "multiplied by the "
         "maintenance factor " +
         format_double("%.2f", scene->settings.maintenance_factor) + ".</p>";
    h += std::string("<p><strong>Accuracy.</strong> The calculation ran at the quality &ldquo;") +
         calc::to_string(scene->settings.quality) +
         "&rdquo;; docs/accuracy.md gives the accuracy each quality "
         "promises. The appendix lists the technical settings.</p>";
  }
  h += "<p><strong>Statistics.</strong> E<sub>min</sub>, E<sub>avg</sub> and E<sub>max</sub>: the "
       "smallest, average and "
       "largest illuminance over the points of a surface; U<sub>0</sub> = E<sub>min</sub> / "
       "E<sub>avg</sub> "
       "(uniformity); U<sub>d</sub> = E<sub>min</sub> / E<sub>max</sub>.</p>";
  return h + "</div>\n";
}

}  // namespace

std::string format_lux_value(double lx) { return format_double("%.1f", lx); }
std::string format_ratio_value(double ratio) { return format_double("%.3f", ratio); }

void base64_to(std::string_view bytes, const TextSink& put) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  // A few kilobytes at a time through a buffer on the stack: a report embeds a megabyte of
  // images, which as one string would be fresh memory (page faults) and a copy into the page.
  constexpr std::size_t kQuads = 4096;
  char buf[4 * kQuads];
  const auto* in = reinterpret_cast<const unsigned char*>(bytes.data());
  const std::size_t whole = bytes.size() / 3;  // complete 3-byte groups
  for (std::size_t g0 = 0; g0 < whole; g0 += kQuads) {
    const std::size_t g1 = std::min(whole, g0 + kQuads);
    char* o = buf;
    for (std::size_t g = g0; g < g1; ++g, o += 4) {
      const unsigned char* b = in + 3 * g;
      const unsigned n = (unsigned{b[0]} << 16) | (unsigned{b[1]} << 8) | b[2];
      o[0] = kAlphabet[(n >> 18) & 63];
      o[1] = kAlphabet[(n >> 12) & 63];
      o[2] = kAlphabet[(n >> 6) & 63];
      o[3] = kAlphabet[n & 63];
    }
    put(std::string_view(buf, static_cast<std::size_t>(o - buf)));
  }
  // One or two bytes left: two or three characters, padded with '=' to a quad.
  const std::size_t i = 3 * whole;
  if (i < bytes.size()) {
    const bool two = i + 1 < bytes.size();
    const unsigned n = (unsigned{in[i]} << 16) | (two ? unsigned{in[i + 1]} << 8 : 0u);
    const char tail[4] = {kAlphabet[(n >> 18) & 63], kAlphabet[(n >> 12) & 63],
                          two ? kAlphabet[(n >> 6) & 63] : '=', '='};
    put(std::string_view(tail, 4));
  }
}

std::string base64(std::string_view bytes) {
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  base64_to(bytes, [&](std::string_view s) { out += s; });
  return out;
}

std::string luminaire_sections_html(const std::vector<LuminaireType>& types,
                                    const calc::Scene& scene) {
  return luminaire_sections(types, scene);
}

std::string html_report(const ReportInput& in) {
  std::string page;
  write_html_report(in, [&](std::string_view s) { page += s; });
  return page;
}

void write_html_report(const ReportInput& in, const TextSink& put) {
  const calc::Results& r = *in.results;
  const calc::Scene* scene = in.scene;
  const std::string project = r.project.empty() ? std::string("Lighting project") : r.project;
  std::string h;
  h += "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
       "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
       "<meta name=\"generator\" content=\"luxgrid " +
       html_escape(in.version) +
       "\">"
       "<title>" +
       html_escape(project) + " - lighting report</title><style>" + style(project, in.date) +
       "</style></head><body>\n";

  // --- cover ----------------------------------------------------------------------------------
  h += "<section class=\"cover\">\n<p class=\"kicker\">Lighting calculation report</p>\n<h1>" +
       html_escape(project) + "</h1>\n<table class=\"meta\">";
  if (scene)
    h += "<tr><th>Project file</th><td>" + html_escape(scene->project_file.filename().string()) +
         "</td></tr>";
  h += "<tr><th>Date</th><td>" + html_escape(in.date) + "</td></tr>";
  if (scene) {
    h += "<tr><th>Rooms</th><td>" + std::to_string(scene->rooms.size()) + "</td></tr>";
    h += "<tr><th>Luminaires</th><td>" + std::to_string(scene->luminaires.size()) + "</td></tr>";
    h += std::string("<tr><th>Calculation quality</th><td data-meta=\"quality\">") +
         calc::to_string(scene->settings.quality) + "</td></tr>";
    h += "<tr><th>Maintenance factor</th><td data-meta=\"maintenance_factor\">" +
         format_double("%.2f", scene->settings.maintenance_factor);
    if (const auto& m = scene->settings.maintenance_parts) {
      h += " = LLMF " + format_double("%.2f", m->LLMF) + " &times; LSF " +
           format_double("%.2f", m->LSF) + " &times; LMF " + format_double("%.2f", m->LMF) +
           " &times; RSMF " + format_double("%.2f", m->RSMF) + " (CIE 97:2005)";
    }
    h += "<br><span class=\"muted\">All illuminances in this report are maintained "
         "values.</span></td></tr>";
  }
  h += lighting_scene_row_html(r.scene);
  if (!in.checks.empty()) {
    const bool ok = all_met(in.checks);
    h += std::string("<tr><th>Requirements</th><td class=\"") + (ok ? "met" : "notmet") + "\">" +
         (ok ? "all met" : "not all met (see Compliance)") + "</td></tr>";
  }
  h += "<tr><th>Calculated with</th><td>luxgrid " + html_escape(in.version) + "</td></tr>";
  h += "</table>\n";
  const std::vector<RoomEnergy>& energy = in.energy;
  h += "</section>\n";

  // --- requirement checks ---------------------------------------------------------------------
  h += compliance_table_html(in.checks);
  if (in.en17037) h += en17037_table_html(*in.en17037);

  // --- rooms ----------------------------------------------------------------------------------
  if (scene && !scene->rooms.empty()) {
    h += "<div class=\"keep\"><h2>Rooms</h2>\n<table class=\"rooms\"><tr><th>Room</th><th "
         "class=\"num\">Floor area</th>"
         "<th class=\"num\">Perimeter</th><th class=\"num\">Size (x &times; y)</th><th "
         "class=\"num\">Height</th>"
         "<th class=\"num\">Reflectance floor / walls / ceiling</th><th class=\"num\">Maintenance "
         "factor</th></tr>";
    for (size_t r = 0; r < scene->rooms.size(); ++r) {
      const calc::Room& room = scene->rooms[r];
      const RoomFigures& figures = in.rooms.at(r);
      h += "<tr data-room=\"" + html_escape(room.name) + "\"><td>" + html_escape(room.name) +
           "</td><td class=\"num\">" + format_double("%.2f", figures.floor_area_m2) +
           " m&sup2;</td><td class=\"num\">" + format_double("%.2f", figures.perimeter_m) +
           " m</td><td class=\"num\">" + format_double("%.2f", figures.size_x_m) + " &times; " +
           format_double("%.2f", figures.size_y_m) + " m</td><td class=\"num\">" +
           format_double("%.2f", room.height) +
           " m</td><td class=\"num\" data-stat=\"reflectance\">" +
           format_double("%.2f", room.reflectance.floor) + " / " +
           format_double("%.2f", room.reflectance.walls) + " / " +
           format_double("%.2f", room.reflectance.ceiling) + "</td><td class=\"num\">" +
           format_double("%.2f", scene->settings.maintenance_factor) + "</td></tr>";
    }
    h += "</table>\n";
    bool any_obstacle = false;
    for (const auto& room : scene->rooms) any_obstacle = any_obstacle || !room.obstacles.empty();
    if (any_obstacle) {
      h += "<table class=\"obstacles\"><tr><th>Room</th><th>Obstacle</th><th class=\"num\">From / "
           "to height</th>"
           "<th class=\"num\">Reflectance</th></tr>";
      for (const auto& room : scene->rooms)
        for (const auto& o : room.obstacles)
          h += "<tr><td>" + html_escape(room.name) + "</td><td>" + html_escape(o.name) +
               "</td><td class=\"num\">" + format_double("%.2f", o.z0) + " / " +
               format_double("%.2f", o.z1) + " m</td><td class=\"num\">" +
               format_double("%.2f", o.reflectance) + "</td></tr>";
      h += "</table>\n";
    }
    h += "</div>\n";
  }

  // --- luminaires -----------------------------------------------------------------------------
  if (scene && !in.types.empty()) {
    h += in.luminaires_html.empty() ? luminaire_sections(in.types, *scene) : in.luminaires_html;
  }

  // --- plan views -----------------------------------------------------------------------------
  if (scene && !scene->rooms.empty()) {
    h += "<h2>Plan view</h2>\n";
    // A daylight site's north angle turns true north away from +y: the arrow shows it.
    const double north_deg = scene->daylight ? scene->daylight->site.north_angle_deg : 0.0;
    const std::string up = north_deg == 0.0 ? "north (+y) up" : "+y up, the arrow to true north";
    for (std::size_t index = 0; index < scene->rooms.size(); ++index) {
      const calc::Room& room = scene->rooms[index];
      std::vector<calc::DaylightOpening> openings;  // the room's
      for (const auto& o : scene->openings)
        if (o.room == index) openings.push_back(o);
      h += "<div class=\"room\"><h3>" + html_escape(room.name) + "</h3>" +
           plan_view_svg(room, scene->luminaires, scene->surfaces, 640, openings, north_deg) +
           "<p class=\"caption\">Seen from above, to scale, " + up +
           ". Yellow: the luminous "
           "opening of each "
           "luminaire at its real size, numbered as in the luminaire table; blue bar: its C0 "
           "direction; red line: "
           "where a tilted luminaire points. Dashed green: calculation surfaces as their real "
           "outline; green bands "
           "along walls: wall grids; crosses: single points (P1, P2, ...); circles with a line: "
           "glare observers and "
           "their view. Walls are numbered as the surfaces named \"&hellip; wall N\" use "
           "them." +
           (openings.empty() ? std::string()
                             : " Blue: daylight openings, a window as the part of its wall it "
                               "takes, a roof light as its outline, dashed.") +
           "</p></div>\n";
    }
  }

  // --- 3D view --------------------------------------------------------------------------------
  if (in.scene_glb) {
    h += "<h2>3D view</h2>\n";
    put(h);
    h.clear();
    SceneViewOptions view;
    view.three_js = in.three_js;
    scene_view_section(*in.scene_glb, view, put);
    h += "<p class=\"caption\">scene.glb beside this report, drawn: rooms grey by reflectance "
         "(walls and ceilings between the eye and the room left out), luminaires with their "
         "luminous opening (yellow) and C0 direction (blue arrow), calculation surfaces coloured "
         "by maintained illuminance on one scale for all (legend; the maps above have one "
         "each). Photometric solids: each luminaire's intensity in every direction, drawn from "
         "its opening, the largest in the scene a third of the highest room.</p>\n";
  }

  // --- energy ---------------------------------------------------------------------------------
  if (!energy.empty()) {
    h += "<div class=\"keep\"><h2>Energy</h2>\n<table class=\"energy\"><tr><th>Room</th><th "
         "class=\"num\">Luminaires</th>"
         "<th class=\"num\">Installed power</th><th class=\"num\">Floor area</th><th "
         "class=\"num\">Power density</th>"
         "<th>Reference surface</th><th class=\"num\">E<sub>avg</sub></th><th class=\"num\">per "
         "100 lx</th></tr>";
    for (const auto& e : energy) {
      const auto na = std::string("&ndash;");
      h += "<tr><td>" + html_escape(e.room) + "</td><td class=\"num\">" +
           std::to_string(e.luminaires) + "</td><td class=\"num\" data-energy=\"power\">" +
           (e.power_W ? format_double("%.1f", *e.power_W) + " W" : na) + "</td><td class=\"num\">" +
           format_double("%.2f", e.area_m2) +
           " m&sup2;</td><td class=\"num\" data-energy=\"density\">" +
           (e.W_per_m2() ? format_double("%.2f", *e.W_per_m2()) + " W/m&sup2;" : na) + "</td><td>" +
           html_escape(e.reference_surface) + "</td><td class=\"num\">" +
           (e.Eavg_lx ? format_lux_value(*e.Eavg_lx) + " lx" : na) +
           "</td><td class=\"num\" data-energy=\"per100lx\">" +
           (e.W_per_m2_per_100lx() ? format_double("%.2f", *e.W_per_m2_per_100lx()) + " W/m&sup2;"
                                   : na) +
           "</td></tr>";
    }
    h += "</table>\n<p class=\"caption\">Installed power: the sum of the power each luminaire's "
         "photometric file "
         "states (with its control gear where the file includes it). Power density: installed "
         "power / floor area. "
         "Per 100 lx: power density / (E<sub>avg</sub> / 100 lx), with E<sub>avg</sub> the "
         "maintained average on the "
         "reference surface (the room's task area, else its workplane, else its floor).";
    for (const auto& e : energy)
      for (const auto& key : e.without_power)
        h += " <strong>" + html_escape(e.room) + ":</strong> the file of &ldquo;" +
             html_escape(key) +
             "&rdquo; gives no power, so the room's energy figures are not given.";
    h += "</p></div>\n";
  }

  // --- daylight (the daylight scene only): sky, site, openings, daylight-factor maps -----------
  h += daylight_section_html(r, scene);

  // --- surfaces -------------------------------------------------------------------------------
  h += "<h2>Calculation surfaces</h2>\n";
  for (const auto& s : r.surfaces) surface_section(s, scene, in, h, put);

  // --- method ---------------------------------------------------------------------------------
  h += method_section(r, scene);
  // --- cost of accuracy ---------------------------------------------------------------------
  if (in.cost && !in.cost->levels.empty()) {
    h += "<h2>What accuracy costs on this project</h2>\n<p>The same project at each quality; "
         "differences are "
         "per point, relative to the <em>reference</em> run (floor: 1 % of the surface maximum); "
         "the estimate is "
         "the plan's own estimate of that difference.</p>\n";
    for (size_t si = 0; si < in.cost->levels.front().surfaces.size(); ++si) {
      h += "<h3>" + html_escape(in.cost->levels.front().surfaces[si].name) +
           "</h3><table><tr><th>Quality</th>"
           "<th class=\"num\">Time</th><th class=\"num\">Eavg</th><th class=\"num\">Emin</th><th "
           "class=\"num\">U0</th>"
           "<th class=\"num\">Max diff</th><th class=\"num\">Estimate</th><th class=\"num\">Mean "
           "diff</th>"
           "<th class=\"num\">Promise</th></tr>";
      for (const auto& l : in.cost->levels) {
        if (si >= l.surfaces.size()) continue;
        const auto& c = l.surfaces[si];
        h += "<tr><td>" + l.quality + "</td><td class=\"num\">" + format_double("%.3f", l.time_s) +
             " s</td><td class=\"num\">" + format_lux_value(c.stats.Eavg) +
             "</td><td class=\"num\">" + format_lux_value(c.stats.Emin) +
             "</td><td class=\"num\">" + format_ratio_value(c.stats.U0) +
             "</td><td class=\"num\">" + format_double("%.3f", 100.0 * c.to_reference.max_rel) +
             " %</td><td class=\"num\">" + format_double("%.3f", 100.0 * c.estimate) + " %" +
             (l.promised_error > 0.0 && c.estimate > l.promised_error ? " (above the promise)"
                                                                      : "") +
             "</td><td class=\"num\">" + format_double("%.3f", 100.0 * c.to_reference.mean_rel) +
             " %</td><td class=\"num\">" +
             (l.promised_error > 0.0 ? format_double("%.3g", 100.0 * l.promised_error) + " %"
                                     : std::string("-")) +
             "</td></tr>";
      }
      h += "</table>\n";
    }
    h += "<table><tr><th>Quality</th><th>Direct</th><th>Reflected</th></tr>";
    for (const auto& l : in.cost->levels) {
      h += "<tr><td>" + l.quality + "</td><td>" + html_escape(l.direct) + "</td><td>" +
           html_escape(l.indirect) + "</td></tr>";
    }
    h += "</table>\n";
  }
  // --- appendix: the technical plan -----------------------------------------------------------
  h += "<h2 class=\"appendix\">Appendix: technical calculation plan</h2>\n<p class=\"caption\">How "
       "luxgrid set up "
       "this calculation, for a lighting engineer who wants to check it (docs/accuracy.md explains "
       "the terms).</p>"
       "<table class=\"plan-text\">";
  h += "<tr><th>Direct light</th><td>" + html_escape(direct_text(r.plan)) + "</td></tr>";
  h += "<tr><th>Reflected light</th><td>" + html_escape(indirect_text(r.plan)) + "</td></tr>";
  h += "<tr><th>Visibility</th><td>" + html_escape(visibility_text(r.plan)) + "</td></tr>";
  for (const auto& n : plan_notes(r.plan))
    h += "<tr><th>Note</th><td>" + html_escape(n) + "</td></tr>";
  h += "</table>\n";
  h += "<p class=\"muted\">Generated by luxgrid " + html_escape(in.version) +
       ".</p>\n</body></html>\n";
  put(h);
}

}  // namespace luxgrid::report
