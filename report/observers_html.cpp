#include "report/observers_html.h"

#include <cmath>
#include <cstdio>

#include "util/format.h"

namespace luxgrid::report {

std::string format_ugr_value(const std::optional<double>& ugr) {
  if (!ugr) return "&ndash;";
  return format_double("%.1f", *ugr);
}

std::string observers_html(const calc::SurfaceResult& s) {
  std::string h =
      "<p>Discomfort glare, UGR (CIE 117), largest over all observers and views: <b "
      "data-ugr-max=\"" +
      format_ugr_value(s.UGR_max) + "\">" + format_ugr_value(s.UGR_max) +
      "</b>. &ndash;: no luminaire in the view's field.</p>\n"
      "<table><tr><th>Observer</th><th>Eye (m)</th><th class=\"num\">View (deg)</th>"
      "<th class=\"num\">UGR</th><th class=\"num\">Lb (cd/m&sup2;)</th><th class=\"num\">E at eye "
      "(lx)</th>"
      "<th class=\"num\">Luminaires</th></tr>";
  size_t point = 0;
  for (size_t k = 0; k < s.observers.size(); ++k) {
    const auto& o = s.observers[k];
    for (const auto& v : o.views) {
      // The view's azimuth from +x, counter-clockwise, and its elevation when not horizontal.
      double az = std::atan2(v.direction.y, v.direction.x) * 180.0 / 3.141592653589793;
      if (az < 0.0) az += 360.0;
      if (std::abs(az) < 0.05 || std::abs(az - 360.0) < 0.05) az = 0.0;
      const double el =
          std::asin(std::max(-1.0, std::min(1.0, v.direction.z))) * 180.0 / 3.141592653589793;
      char buf[400];
      std::snprintf(
          buf, sizeof buf,
          "<tr><td>%zu</td><td>%.2f, %.2f, %.2f</td><td class=\"num\">%.1f%s</td><td "
          "class=\"num\">%s</td>"
          "<td class=\"num\">%.1f</td><td class=\"num\">%.1f</td><td class=\"num\">%zu</td></tr>",
          k + 1, o.at.x, o.at.y, o.at.z, az,
          std::abs(el) >= 0.05 ? (" / " + std::to_string(static_cast<int>(std::lround(el)))).c_str()
                               : "",
          format_ugr_value(v.UGR).c_str(), v.Lb_cd_m2, point < s.E.size() ? s.E[point] : 0.0,
          v.terms.size());
      h += buf;
      ++point;
    }
  }
  h += "</table>\n";
  return h;
}

}  // namespace luxgrid::report
