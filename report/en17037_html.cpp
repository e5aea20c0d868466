#include "report/en17037_html.h"

#include "report/html_text.h"
#include "util/format.h"

namespace luxgrid::report {

namespace {

std::string en17037_criterion_cells(const daylight::En17037Criterion& c) {
  return "<td class=\"num\">" + number_text(c.illuminance_lx) + " lx</td><td class=\"num\">" +
         format_double("%.2f", c.daylight_factor_percent) + " %</td><td class=\"num\">" +
         format_double("%g", 100.0 * c.required_fraction) + " %</td><td class=\"num\">" +
         format_double("%.1f", 100.0 * c.fraction) + " %</td><td class=\"" +
         (c.met ? "met" : "notmet") + "\">" + (c.met ? "met" : "not met") + "</td>";
}

}  // namespace

std::string en17037_table_html(const daylight::En17037Assessment& a) {
  std::string h =
      "<div class=\"keep\" id=\"en17037\"><h2>Daylight provision (EN 17037)</h2>\n"
      "<p class=\"muted\">Daylight-factor method: each level's target illuminance E<sub>T</sub> "
      "over 50 % of the reference plane (95 % where the space is top-lit) and its minimum "
      "target E<sub>TM</sub> over 95 %, as daylight factors D = E / E<sub>v,d,med</sub> at the "
      "site's median external diffuse illuminance E<sub>v,d,med</sub> = " +
      number_text(a.median_external_diffuse_lx) +
      " lx. Level asked: " + daylight::to_string(a.asked) + ".</p>\n";
  for (const daylight::En17037PlaneResult& p : a.planes) {
    h += "<h3>" + html_escape(p.surface) + " <span class=\"muted\">(" +
         (p.top_lit ? "top-lit" : "side-lit") + ", " + std::to_string(p.points) +
         " points)</span></h3>\n<p>Average daylight factor <span data-en17037=\"DF_average\">" +
         format_double("%.2f", p.DF_average_percent) + " %</span>, minimum " +
         format_double("%.2f", p.DF_min_percent) +
         " %, uniformity D<sub>min</sub> / "
         "D<sub>average</sub> " +
         format_double("%.3f", p.uniformity) +
         "; level reached: <b data-en17037=\"level_achieved\">" +
         (p.achieved ? daylight::to_string(*p.achieved) : "none") + "</b>.</p>\n";
    h += "<table class=\"en17037\" data-surface=\"" + html_escape(p.surface) +
         "\"><tr><th>Level</th><th>Target</th><th class=\"num\">Illuminance</th><th "
         "class=\"num\">Daylight factor</th><th class=\"num\">Plane required</th><th "
         "class=\"num\">Plane reaching</th><th>Result</th></tr>";
    for (const auto& l : p.levels) {
      const bool asked = l.level == a.asked;
      const std::string name =
          std::string(daylight::to_string(l.level)) + (asked ? " (asked)" : "");
      h += "<tr data-level=\"" + std::string(daylight::to_string(l.level)) +
           "\"><td rowspan=\"2\">" + (asked ? "<b>" + name + "</b>" : name) +
           "</td><td>E<sub>T</sub></td>" + en17037_criterion_cells(l.target) + "</tr>";
      h += "<tr><td>E<sub>TM</sub></td>" + en17037_criterion_cells(l.minimum_target) + "</tr>";
    }
    h += "</table>\n";
  }
  h += "</div>\n";
  return h;
}

}  // namespace luxgrid::report
