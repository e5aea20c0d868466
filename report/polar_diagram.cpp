#include "report/polar_diagram.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "photometry/derived_photometry.h"
#include "report/colour_scale.h"

namespace luxgrid::report {

namespace {
constexpr double kStepDeg = 2.5;  // 145 samples per plane: smooth at 220 px, cheap to compute
}

std::string polar_diagram_svg(const photometry::IntensityDistribution& d, int size_px) {
  const double c = size_px / 2.0, radius = size_px / 2.0 - 18.0;
  const int n = static_cast<int>(360.0 / kStepDeg);
  std::vector<double> a(n + 1), b(n + 1);
  double imax = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double s = -180.0 + k * kStepDeg;
    a[k] = photometry::plane_intensity(d, 0.0, s);
    b[k] = photometry::plane_intensity(d, 90.0, s);
    imax = std::max({imax, a[k], b[k]});
  }
  const double outer = nice_ceil(imax);
  char buf[256];
  std::string svg;
  std::snprintf(buf, sizeof buf,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"polar\" width=\"%d\" height=\"%d\" "
                "viewBox=\"0 0 %d %d\" font-family=\"DejaVu Sans, sans-serif\" font-size=\"9\">",
                size_px, size_px, size_px, size_px);
  svg += buf;
  // Rings at quarters of the outer value, spokes every 30 degrees.
  for (int q = 1; q <= 4; ++q) {
    std::snprintf(buf, sizeof buf, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"none\" stroke=\"#bbb\" stroke-width=\"0.6\"/>",
                  c, c, radius * q / 4.0);
    svg += buf;
    std::snprintf(buf, sizeof buf, "<text x=\"%.1f\" y=\"%.1f\" fill=\"#555\">%g</text>", c + 2, c - radius * q / 4.0 + 9,
                  outer * q / 4.0);
    svg += buf;
  }
  for (int deg = 0; deg < 180; deg += 30) {
    const double r = deg * kDegToRad;
    std::snprintf(buf, sizeof buf, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\" stroke-width=\"0.6\"/>",
                  c - radius * std::sin(r), c - radius * std::cos(r), c + radius * std::sin(r), c + radius * std::cos(r));
    svg += buf;
  }
  // Signed angle s from nadir: s > 0 to the right (C0 or C90), nadir at the bottom.
  auto curve = [&](const std::vector<double>& v, const char* style) {
    std::string pts;
    for (int k = 0; k <= n; ++k) {
      const double s = (-180.0 + k * kStepDeg) * kDegToRad;
      const double r = outer > 0.0 ? radius * v[k] / outer : 0.0;
      std::snprintf(buf, sizeof buf, "%.1f,%.1f ", c + r * std::sin(s), c + r * std::cos(s));
      pts += buf;
    }
    return "<polyline fill=\"none\" " + std::string(style) + " points=\"" + pts + "\"/>";
  };
  svg += curve(a, "stroke=\"#1f3f8f\" stroke-width=\"1.6\"");
  svg += curve(b, "stroke=\"#c0392b\" stroke-width=\"1.4\" stroke-dasharray=\"4 3\"");
  std::snprintf(buf, sizeof buf,
                "<text x=\"4\" y=\"11\" fill=\"#1f3f8f\">&#8212; C0-C180</text>"
                "<text x=\"4\" y=\"22\" fill=\"#c0392b\">- - C90-C270</text>"
                "<text x=\"%d\" y=\"11\" text-anchor=\"end\" fill=\"#555\">cd</text></svg>",
                size_px - 4);
  svg += buf;
  return svg;
}

}  // namespace luxgrid::report
