#include "report/polar_diagram.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "photometry/derived_photometry.h"
#include "report/colour_scale.h"
#include "report/raster_text.h"

namespace luxgrid::report {

namespace {
constexpr double kStepDeg = kPolarStepDeg;
// The plane colours, the same in every diagram luxgrid draws.
const Rgb kC0{0.12f, 0.25f, 0.56f}, kC90{0.75f, 0.22f, 0.17f};
const Rgb kRing{0.78f, 0.78f, 0.78f}, kGreyText{0.33f, 0.33f, 0.33f}, kBlack{0, 0, 0},
    kWhite{1, 1, 1};
}  // namespace

double polar_outer_ring_cd(double imax_cd) { return nice_ceil(imax_cd); }

PolarCurves polar_curves(const photometry::IntensityDistribution& d) {
  const int n = static_cast<int>(360.0 / kStepDeg);
  PolarCurves out;
  out.c0_cd.resize(n + 1);
  out.c90_cd.resize(n + 1);
  for (int i = 0; i <= n; ++i) {
    const double s = -180.0 + i * kStepDeg;
    out.c0_cd[i] = photometry::plane_intensity(d, 0.0, s);
    out.c90_cd[i] = photometry::plane_intensity(d, 90.0, s);
  }
  return out;
}

Raster polar_diagram(const photometry::IntensityDistribution& d, const std::string& title,
                     int size_px, bool* font_ok) {
  return polar_diagram(polar_curves(d), title, size_px, font_ok);
}

Raster polar_diagram(const PolarCurves& curves, const std::string& title, int size_px,
                     bool* font_ok) {
  const double k = size_px / 640.0;  // everything below is laid out for 640 px and scaled
  const int title_h = static_cast<int>(std::lround(34 * k)),
            legend_h = static_cast<int>(std::lround(30 * k));
  // Text about 1/36 of the side: 18 px on `info --plot`'s 640 px, readable when the report shows
  // its 600 px diagram 300 px wide.
  const int font_px = std::max(9, size_px / 36);
  const double cx = size_px / 2.0, cy = title_h + (size_px - title_h - legend_h) / 2.0;
  const double radius = (size_px - title_h - legend_h) / 2.0 - 26 * k;
  const std::vector<double>& a = curves.c0_cd;
  const std::vector<double>& b = curves.c90_cd;
  const int n = static_cast<int>(std::min(a.size(), b.size())) - 1;
  double imax = 0.0;
  for (int i = 0; i <= n; ++i) imax = std::max({imax, a[i], b[i]});
  const double ring = polar_outer_ring_cd(imax);
  Raster img(size_px, size_px, kWhite);
  bool fonts = true;
  auto text = [&](double x, double y, const std::string& s, Rgb colour, bool centred = false) {
    const int w = centred ? text_width(s, font_px, kPlotFont) : 0;
    fonts = draw_text(img, static_cast<int>(std::lround(x)) - w / 2,
                      static_cast<int>(std::lround(y)), s, font_px, kPlotFont, colour) &&
            fonts;
  };
  // Point at signed angle s from nadir (deg; > 0 towards the right: C0 or C90) and radius r px.
  auto xy = [&](double s_deg, double r, double& x, double& y) {
    const double t = s_deg * kDegToRad;
    x = cx + r * std::sin(t);
    y = cy + r * std::cos(t);  // image y grows downwards: nadir at the bottom
  };
  const int thick = std::max(1, static_cast<int>(std::lround(2 * k)));
  auto seg = [&](double x0, double y0, double x1, double y1, Rgb c, int w) {
    for (int t = 0; t < w; ++t) {
      const int o = t - w / 2;
      const bool steep = std::abs(y1 - y0) > std::abs(x1 - x0);
      img.line(int(std::lround(x0)) + (steep ? o : 0), int(std::lround(y0)) + (steep ? 0 : o),
               int(std::lround(x1)) + (steep ? o : 0), int(std::lround(y1)) + (steep ? 0 : o), c);
    }
  };
  for (int q = 1; q <= 4; ++q) {  // rings at quarters of the outer value
    for (int deg = 0; deg < 360; ++deg) {
      double x0, y0, x1, y1;
      xy(deg, radius * q / 4.0, x0, y0);
      xy(deg + 1, radius * q / 4.0, x1, y1);
      seg(x0, y0, x1, y1, kRing, 1);
    }
  }
  for (int deg = 0; deg < 360; deg += 30) {  // spokes and their angles (0 at nadir, 180 at zenith)
    double x, y;
    xy(deg, radius, x, y);
    seg(cx, cy, x, y, kRing, 1);
    xy(deg, radius + 14 * k, x, y);
    const int shown = deg <= 180 ? deg : 360 - deg;
    text(x, y + font_px / 2.0 - 1, std::to_string(shown) + "\xC2\xB0", kGreyText, true);
  }
  auto curve = [&](const std::vector<double>& v, Rgb colour, bool dashed) {
    for (int i = 0; i + 1 <= n; ++i) {
      if (dashed && (i / 8) % 2 == 1) continue;  // 4 degree dashes
      double x0, y0, x1, y1;
      xy(-180.0 + kStepDeg * i, ring > 0 ? radius * v[i] / ring : 0.0, x0, y0);
      xy(-180.0 + kStepDeg * (i + 1), ring > 0 ? radius * v[i + 1] / ring : 0.0, x1, y1);
      seg(x0, y0, x1, y1, colour, thick);
    }
  };
  curve(a, kC0, false);
  curve(b, kC90, true);
  // Ring values beside the upward spoke, on white so the curves do not hide them.
  for (int q = 1; q <= 4; ++q) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", ring * q / 4.0);
    const int w = text_width(buf, font_px, kPlotFont);
    const double y =
        cy - radius * q / 4.0 + font_px + 2;  // just inside the ring, clear of the 180 deg label
    img.fill(int(cx) + 3, int(cx) + 3 + w + 4, int(y) - font_px + 2, int(y) + 3, kWhite);
    text(cx + 5, y, buf, kGreyText);
  }
  text(cx, 22 * k + font_px / 3.0, title + "  (cd)", kBlack, true);
  const double ly = size_px - 10 * k;
  seg(12 * k, ly - font_px / 3.0, 40 * k, ly - font_px / 3.0, kC0, thick);
  text(46 * k, ly, "C0-C180", kC0);
  const double rx = size_px / 2.0 + 12 * k;
  for (int dash = 0; dash < 3; ++dash)
    seg(rx + dash * 10 * k, ly - font_px / 3.0, rx + dash * 10 * k + 6 * k, ly - font_px / 3.0,
        kC90, thick);
  text(rx + 34 * k, ly, "C90-C270", kC90);
  if (font_ok) *font_ok = fonts;
  return img;
}

}  // namespace luxgrid::report
