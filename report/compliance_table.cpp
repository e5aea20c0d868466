#include "report/compliance_table.h"

#include <algorithm>
#include <cstdio>
#include <set>

#include "report/en17037_checks.h"
#include "report/html_report.h"
#include "report/requirement_checks_en1838.h"
#include "util/format.h"

namespace luxgrid::report {

namespace {

// Digits as a designer reads them: lux to 0.1, ratios to 0.001, UGR and Ra to 0.1.
const char* format_of(const std::string& q) {
  if (q == "U0" || q == "modelling") return "%.3f";
  return "%.1f";
}

const char* quantity_label(const std::string& q) {
  if (q == "Em") return "E<sub>m</sub>";
  if (q == "U0") return "U<sub>0</sub>";
  if (q == "Emin") return "E<sub>min</sub>";
  if (q == "Emax") return "E<sub>max</sub>";
  if (q == "Ez") return "E<sub>z</sub> (cylindrical)";
  if (q == "Esc") return "E<sub>sc</sub> (semi-cylindrical)";
  if (q == "modelling") return "Modelling E<sub>z</sub> / E<sub>h</sub>";
  if (q == "UGR_L") return "UGR<sub>L</sub>";
  if (q == kDiversityQuantity) return "E<sub>max</sub> / E<sub>min</sub>";
  if (q == kEn17037TargetQuantity) return "Plane with D &ge; D<sub>T</sub> (EN 17037)";
  if (q == kEn17037MinimumTargetQuantity) return "Plane with D &ge; D<sub>TM</sub> (EN 17037)";
  return "R<sub>a</sub>";
}

}  // namespace

std::string lighting_scene_row_html(calc::LightingScene scene) {
  if (scene == calc::LightingScene::normal) return "";
  return "<tr><th>Scene</th><td data-meta=\"scene\">emergency (EN 1838): direct light only, "
         "emergency output of "
         "the emergency luminaires</td></tr>";
}

const char* check_result(const RequirementCheck& c) {
  if (!c.calculated) return "not calculated";
  return c.met ? "met" : "not met";
}

std::string compliance_table_html(const std::vector<RequirementCheck>& checks) {
  if (checks.empty()) return "";
  const bool ok = all_met(checks);
  size_t missing = 0, failed = 0;
  for (const auto& c : checks) {
    missing += c.calculated ? 0 : 1;
    failed += c.calculated && !c.met ? 1 : 0;
  }
  std::string verdict = ok ? "All requirements are met." : "Some requirements are NOT met";
  if (!ok) {
    verdict += " (" + std::to_string(failed) + " not met, " + std::to_string(missing) +
               " not calculated).";
  }
  // The emergency scene's checks are EN 1838's, on escape routes and open areas.
  const bool emergency = std::any_of(checks.begin(), checks.end(), [](const RequirementCheck& c) {
    return c.fixed_by_standard && c.source.rfind("EN 1838", 0) == 0;
  });
  std::string h = std::string(emergency ? "<h2>Compliance: emergency lighting (EN 1838)</h2>\n"
                                        : "<h2>Compliance</h2>\n");
  if (emergency) {
    h += "<p class=\"muted\">Direct light only, from the luminaires with an emergency entry at "
         "their emergency "
         "output; horizontal illuminance on the floor. Escape routes: centre line E<sub>min</sub> "
         "&ge; 1 lx and "
         "E<sub>max</sub> / E<sub>min</sub> &le; 40, central band (half the route's width) "
         "E<sub>min</sub> &ge; "
         "0.5 lx; open areas, without a 0.5 m border: E<sub>min</sub> &ge; 0.5 lx and "
         "E<sub>max</sub> / "
         "E<sub>min</sub> &le; 40.</p>\n";
  }
  h += "<p class=\"" + std::string(ok ? "met" : "notmet") + "\" data-requirements=\"" +
       (ok ? "met" : "not met") + "\">" + verdict + "</p>\n";
  h += "<table class=\"compliance\"><tr><th>Surface</th><th>Quantity</th><th "
       "class=\"num\">Required</th>"
       "<th class=\"num\">Achieved</th><th>Result</th><th "
       "class=\"num\">Margin</th><th>Source</th></tr>";
  std::set<std::string> citations;
  std::string previous;
  for (const auto& c : checks) {
    const std::string unit = requirement_unit(c.quantity);
    const char* f = format_of(c.quantity);
    const std::string required = c.required_max ? format_double(f, c.required) + " &ndash; " +
                                                      format_double(f, *c.required_max)
                                                : std::string(c.upper_limit ? "&le; " : "&ge; ") +
                                                      format_double("%g", c.required) + unit;
    std::string achieved = "&ndash;", margin = "&ndash;";
    if (c.calculated) {
      achieved = c.achieved_max ? format_double(f, c.achieved) + " &ndash; " +
                                      format_double(f, *c.achieved_max)
                                : format_double(f, c.achieved) + unit;
      const std::string mf = std::string("%+") + (f + 1);
      margin = format_double(mf.c_str(), c.margin) + unit + "<br><span class=\"muted\">" +
               format_double("%+.1f", 100.0 * c.margin_rel) + " %</span>";
    }
    const char* result = check_result(c);
    const char* css = !c.calculated ? "notcalc" : c.met ? "met" : "notmet";
    std::string source = c.fixed_by_standard ? html_escape(c.source)
                         : c.source.empty()
                             ? "stated"
                             : "preset " + html_escape(c.source.substr(0, c.source.find(':')));
    if (!c.source.empty() && !c.fixed_by_standard) citations.insert(c.source);
    if (!c.note.empty()) source += "<br><span class=\"muted\">" + html_escape(c.note) + "</span>";
    const std::string surface =
        c.surface == previous
            ? ""
            : html_escape(c.surface) + " <span class=\"muted\">(" + c.role + ")</span>";
    previous = c.surface;
    h += "<tr data-check=\"" + html_escape(c.surface + "|" + c.quantity) + "\" data-result=\"" +
         result + "\"><td>" + surface + "</td><td>" + quantity_label(c.quantity) +
         "</td><td class=\"num\">" + required + "</td><td class=\"num\">" + achieved +
         "</td><td class=\"" + css + "\">" + result + "</td><td class=\"num\">" + margin +
         "</td><td>" + source + "</td></tr>";
  }
  h += "</table>\n";
  if (!citations.empty()) {
    h += "<p class=\"muted\">Preset limits: ";
    bool first = true;
    for (const auto& cite : citations) {
      h += (first ? "" : "; ") + html_escape(cite);
      first = false;
    }
    h += ".</p>\n";
  }
  return h;
}

}  // namespace luxgrid::report
