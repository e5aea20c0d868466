#include "report/html_report.h"

#include <cstdio>

#include "calc/glare/ugr_table.h"
#include "photometry/derived_photometry.h"
#include "report/compliance_table.h"
#include "report/observers_html.h"
#include "report/plan_view_svg.h"
#include "report/polar_diagram.h"

namespace luxgrid::report {

namespace {

// Grids up to this many points per side get their values printed as a table (EN 12464-1 asks for
// the grid values to be documented; beyond 30 x 30 a table no longer fits a printed page).
constexpr int kMaxValueTableSide = 30;

constexpr const char* kStyle = R"(
body { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; font-size: 10.5pt; color: #111;
       max-width: 190mm; margin: 1.5em auto; padding: 0 1em; line-height: 1.35; }
h1 { font-size: 18pt; margin: 0 0 .2em; } h2 { font-size: 13.5pt; border-bottom: 1.5px solid #333;
     margin-top: 1.4em; } h3 { font-size: 11.5pt; margin: 1em 0 .3em; }
table { border-collapse: collapse; margin: .4em 0; } td, th { border: 1px solid #bbb; padding: 2px 6px;
     text-align: left; vertical-align: top; } th { background: #eee; }
td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; }
table.values { font-size: 6.5pt; } table.values td { padding: 0 2px; text-align: right; border-color: #ddd; }
.met { color: #0a6b2f; font-weight: bold; } .notmet { color: #a10f0f; font-weight: bold; }
.notcalc { color: #8a5a00; font-weight: bold; } table.compliance { font-size: 9.5pt; } table.compliance td.num { white-space: nowrap; }
table.compliance td:last-child { overflow-wrap: anywhere; }
.surface { break-inside: avoid; page-break-inside: avoid; } .surface img { max-width: 100%; height: auto; }
.plan, .polar { max-width: 100%; height: auto; } .luminaire-card { display: inline-block; margin: 0 1em 1em 0;
     vertical-align: top; break-inside: avoid; } .muted { color: #666; }
@page { size: A4; margin: 14mm 12mm; }
@media print { body { margin: 0; padding: 0; max-width: none; } h2 { break-after: avoid; }
  .surface, .room, table.values, .luminaire-card { break-inside: avoid; } a { color: inherit; } }
)";

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

std::string stat_cell(const std::string& surface, const char* key, const std::string& text) {
  return "<td class=\"num\" data-surface=\"" + html_escape(surface) + "\" data-stat=\"" + key + "\">" + text + "</td>";
}

}  // namespace

std::string format_lux_value(double lx) { return fmt("%.1f", lx); }
std::string format_ratio_value(double ratio) { return fmt("%.3f", ratio); }

std::string html_escape(const std::string& s) {
  std::string out;
  for (char ch : s) {
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += ch;
    }
  }
  return out;
}

std::string base64(const std::string& bytes) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned n = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += kAlphabet[(n >> 18) & 63];
    out += kAlphabet[(n >> 12) & 63];
    out += kAlphabet[(n >> 6) & 63];
    out += kAlphabet[n & 63];
  }
  if (i + 1 == bytes.size()) {
    const unsigned n = static_cast<unsigned char>(bytes[i]) << 16;
    out += kAlphabet[(n >> 18) & 63];
    out += kAlphabet[(n >> 12) & 63];
    out += "==";
  } else if (i + 2 == bytes.size()) {
    const unsigned n = (static_cast<unsigned char>(bytes[i]) << 16) | (static_cast<unsigned char>(bytes[i + 1]) << 8);
    out += kAlphabet[(n >> 18) & 63];
    out += kAlphabet[(n >> 12) & 63];
    out += kAlphabet[(n >> 6) & 63];
    out += '=';
  }
  return out;
}

std::string html_report(const ReportInput& in) {
  const calc::Results& r = *in.results;
  const calc::Scene* scene = in.scene;
  std::string h;
  h += "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
       "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
       "<meta name=\"generator\" content=\"luxgrid " + html_escape(in.version) + "\">"
       "<title>" + html_escape(r.project) + " - luxgrid report</title><style>" + kStyle + "</style></head><body>\n";
  h += "<h1>" + html_escape(r.project) + "</h1>\n<p class=\"muted\">Lighting calculation report</p>\n";

  // --- what this is -------------------------------------------------------------------------
  h += "<table class=\"meta\">";
  h += "<tr><th>Date</th><td>" + html_escape(in.date) + "</td></tr>";
  h += "<tr><th>luxgrid version</th><td>" + html_escape(in.version) + "</td></tr>";
  if (scene) {
    h += "<tr><th>Project file</th><td>" + html_escape(scene->project_file.filename().string()) + "</td></tr>";
    h += std::string("<tr><th>Quality</th><td data-meta=\"quality\">") + calc::to_string(scene->settings.quality) + "</td></tr>";
    h += "<tr><th>Maintenance factor</th><td data-meta=\"maintenance_factor\">" +
         fmt("%.2f", scene->settings.maintenance_factor);
    if (const auto& m = scene->settings.maintenance_parts) {
      h += " = LLMF " + fmt("%.2f", m->LLMF) + " &times; LSF " + fmt("%.2f", m->LSF) + " &times; LMF " +
           fmt("%.2f", m->LMF) + " &times; RSMF " + fmt("%.2f", m->RSMF) + " (CIE 97:2005)";
    }
    h += " (all illuminances are maintained values)</td></tr>";
  }
  h += "</table>\n";

  // --- requirement checks -------------------------------------------------------------------
  h += compliance_table_html(in.checks);

  // --- what was simulated -------------------------------------------------------------------
  h += "<h2>What was calculated</h2>\n<table>";
  h += "<tr><th>Direct light</th><td>" + html_escape(r.plan.direct) + "</td></tr>";
  h += "<tr><th>Reflected light</th><td>" + html_escape(r.plan.indirect) + "</td></tr>";
  h += "<tr><th>Visibility</th><td>" + html_escape(r.plan.visibility) + "</td></tr>";
  for (const auto& n : r.plan.notes) h += "<tr><th>Note</th><td>" + html_escape(n) + "</td></tr>";
  h += "</table>\n\n";

  // --- plan views ---------------------------------------------------------------------------
  if (scene && !scene->rooms.empty()) {
    h += "<h2>Plan view</h2>\n";
    for (const auto& room : scene->rooms) {
      h += "<div class=\"room\"><h3>" + html_escape(room.name) + "</h3>" +
           plan_view_svg(room, scene->luminaires, scene->surfaces) +
           "<p class=\"muted\">Seen from above, north (+y) up. Circles: luminaires (numbered, the bar "
           "along C0), red line: aiming of tilted luminaires; dashed: calculation grids.</p></div>\n";
    }
  }

  // --- surfaces -----------------------------------------------------------------------------
  h += "<h2>Calculation surfaces</h2>\n";
  for (const auto& s : r.surfaces) {
    const auto& g = s.grid;
    const bool grid = g.kind == geometry::SurfaceGrid::Kind::grid;
    h += "<div class=\"surface\" data-surface=\"" + html_escape(g.name) + "\"><h3>" + html_escape(g.name) + "</h3>\n";
    const auto png = in.png.find(g.name);
    if (png != in.png.end()) {
      h += "<img alt=\"false-colour illuminance of " + html_escape(g.name) + "\" src=\"data:image/png;base64," +
           base64(png->second) + "\">\n";
    }
    h += "<table><tr><th class=\"num\">Emin</th><th class=\"num\">Eavg</th><th class=\"num\">Emax</th>"
         "<th class=\"num\">U0</th><th class=\"num\">Ud</th><th>Points</th></tr><tr>";
    h += stat_cell(g.name, "Emin", format_lux_value(s.stats.Emin) + " lx");
    h += stat_cell(g.name, "Eavg", format_lux_value(s.stats.Eavg) + " lx");
    h += stat_cell(g.name, "Emax", format_lux_value(s.stats.Emax) + " lx");
    h += stat_cell(g.name, "U0", format_ratio_value(s.stats.U0));
    h += stat_cell(g.name, "Ud", format_ratio_value(s.stats.Ud));
    h += grid ? "<td>" + std::to_string(g.nu) + " x " + std::to_string(g.nv) + ", spacing " + fmt("%.3f", g.spacing_u) +
                    " x " + fmt("%.3f", g.spacing_v) + " m</td>"
              : "<td>" + std::to_string(g.points.size()) + " points</td>";
    h += "</tr></table>\n";
    if (grid && g.nu <= kMaxValueTableSide && g.nv <= kMaxValueTableSide) {
      h += "<details open><summary>Values in lx (rows from the far edge, v, to the near edge; columns along u)</summary>"
           "<table class=\"values\">";
      for (int j = g.nv - 1; j >= 0; --j) {
        h += "<tr>";
        for (int i = 0; i < g.nu; ++i) {
          const size_t k = static_cast<size_t>(j) * g.nu + i;
          const bool on = k >= g.active.size() || g.active[k];
          h += "<td>" + (on && k < s.E.size() ? fmt("%.0f", s.E[k]) : std::string("&ndash;")) + "</td>";
        }
        h += "</tr>";
      }
      h += "</table></details>\n";
    } else if (g.kind == geometry::SurfaceGrid::Kind::observers) {
      h += observers_html(s);
    } else if (!grid) {
      h += "<table><tr><th>Point</th><th>Position (m)</th><th class=\"num\">E (lx)</th></tr>";
      for (size_t k = 0; k < g.points.size() && k < s.E.size(); ++k) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "<tr><td>%zu</td><td>%.3f, %.3f, %.3f</td><td class=\"num\">%.1f</td></tr>", k + 1,
                      g.points[k].x, g.points[k].y, g.points[k].z, s.E[k]);
        h += buf;
      }
      h += "</table>\n";
    }
    h += "</div>\n";
  }

  // --- luminaire schedule -------------------------------------------------------------------
  if (scene && !scene->photometry.empty()) {
    h += "<h2>Luminaire schedule</h2>\n<table><tr><th>Entry</th><th>File</th><th>Description</th>"
         "<th class=\"num\">Count</th><th class=\"num\">Flux (lm)</th><th class=\"num\">LOR</th>"
         "<th class=\"num\">UGR 4H&times;8H (CIE 190, 0.7/0.5/0.2, crosswise / endwise)</th></tr>";
    std::string cards;
    for (const auto& [key, p] : scene->photometry) {
      int count = 0;
      for (const auto& l : scene->luminaires) count += l.photometry == key ? 1 : 0;
      const auto d = photometry::derive(p);
      std::string desc;
      for (const auto& [k, v] : p.keywords) {
        if (k.empty() || k[0] == '_') continue;
        if (!desc.empty()) desc += "<br>";
        desc += html_escape(k) + ": " + html_escape(v);
      }
      if (desc.empty()) desc = html_escape(p.format);
      const auto lor = d.lor ? d.lor : p.stated_lor;
      h += "<tr><td>" + html_escape(key) + "</td><td>" + html_escape(p.source) + "</td><td>" + desc +
           "</td><td class=\"num\">" + std::to_string(count) + "</td><td class=\"num\">" + fmt("%.0f", d.flux_lm) +
           "</td><td class=\"num\">" + (lor ? fmt("%.2f", *lor) : std::string("&ndash;")) + "</td>";
      const photometry::IntensityDistribution* dist = p.distribution.get();
      const photometry::LuminousOpening* opening = &p.opening;
      for (const auto& l : scene->luminaires) {
        if (l.photometry == key && l.distribution) {
          dist = l.distribution.get();  // as used: a project flux_lm or multiplier applied
          opening = &l.opening;         // and the project's "emitter", if any
          break;
        }
      }
      // CIE 190's 4H x 8H value at 0.7/0.5/0.2 (crosswise / endwise) for the luminaire as used:
      // the 1000 lm table plus 8 log10(F / 1000) is the UGR of the distribution itself.
      std::string ugr = "&ndash;";
      if (dist && opening->shape != photometry::LuminousOpening::Shape::point) {
        const calc::glare::TableRoom room{4, 8};
        const auto c = calc::glare::table_ugr(*dist, *opening, room, calc::glare::kTableReflectances[0],
                                              calc::glare::Viewing::crosswise);
        const auto e = calc::glare::table_ugr(*dist, *opening, room, calc::glare::kTableReflectances[0],
                                              calc::glare::Viewing::endwise);
        if (c && e) ugr = fmt("%.1f", *c) + " / " + fmt("%.1f", *e);
      }
      h += "<td class=\"num\" data-ugr-table=\"" + html_escape(key) + "\">" + ugr + "</td></tr>";
      if (dist) {
        cards += "<div class=\"luminaire-card\"><h3>" + html_escape(key) + "</h3>" + polar_diagram_svg(*dist) + "</div>";
      }
    }
    h += "</table>\n" + cards + "\n";
  }

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
        h += "<tr><td>" + l.quality + "</td><td class=\"num\">" + fmt("%.3f", l.time_s) +
             " s</td><td class=\"num\">" + format_lux_value(c.stats.Eavg) +
             "</td><td class=\"num\">" + format_lux_value(c.stats.Emin) +
             "</td><td class=\"num\">" + format_ratio_value(c.stats.U0) +
             "</td><td class=\"num\">" + fmt("%.3f", 100.0 * c.to_reference.max_rel) +
             " %</td><td class=\"num\">" + fmt("%.3f", 100.0 * c.estimate) + " %" +
             (l.promised_error > 0.0 && c.estimate > l.promised_error ? " (above the promise)"
                                                                      : "") +
             "</td><td class=\"num\">" + fmt("%.3f", 100.0 * c.to_reference.mean_rel) +
             " %</td><td class=\"num\">" +
             (l.promised_error > 0.0 ? fmt("%.3g", 100.0 * l.promised_error) + " %"
                                     : std::string("-")) +
             "</td></tr>";
      }
      h += "</table>\n";
    }
    h += "<table><tr><th>Quality</th><th>Direct</th><th>Reflected</th></tr>";
    for (const auto& l : in.cost->levels) {
      h += "<tr><td>" + l.quality + "</td><td>" + html_escape(l.direct) + "</td><td>" + html_escape(l.indirect) + "</td></tr>";
    }
    h += "</table>\n";
  }
  h += "<p class=\"muted\">Generated by luxgrid " + html_escape(in.version) + ".</p>\n</body></html>\n";
  return h;
}

}  // namespace luxgrid::report
