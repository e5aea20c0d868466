#include "report/false_colour.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include "report/isolux.h"
#include "util/error.h"

namespace luxgrid::report {

namespace OIIO = OIIO_NAMESPACE;

namespace {

constexpr const char* kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr int kPlotTargetPx = 480;  // the longer side of the map, before rounding to whole cells
constexpr int kTitleH = 56, kMargin = 16, kLegendW = 150, kBarW = 22, kFontPx = 14;

std::string format_lux(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, v >= 100 || v == std::floor(v) ? "%.0f" : "%.1f", v);
  return buf;
}

}  // namespace

bool plot_position(const geometry::SurfaceGrid& g, const Vec3& world, double& fx, double& fy) {
  // 0.7 ~ cos 45 deg: floors, workplanes and ceilings get marks; walls do not.
  constexpr double kHorizontalNormalZ = 0.7;
  const Vec3 n = glm::cross(g.u_dir, g.v_dir);
  if (std::abs(n.z) < kHorizontalNormalZ || !(g.size_u > 0.0) || !(g.size_v > 0.0)) return false;
  const Vec3 rel = world - g.origin;
  const double u = glm::dot(rel, g.u_dir), v = glm::dot(rel, g.v_dir);
  if (u < 0.0 || u > g.size_u || v < 0.0 || v > g.size_v) return false;
  fx = u / g.size_u;
  fy = 1.0 - v / g.size_v;
  return true;
}

std::string write_false_colour_png(const calc::SurfaceResult& r, const ColourScale& scale,
                                   const std::filesystem::path& path) {
  return write_false_colour_png(r, scale, path, PlotOverlay{});
}

std::string write_false_colour_png(const calc::SurfaceResult& r, const ColourScale& scale,
                                   const std::filesystem::path& path, const PlotOverlay& overlay) {
  const auto& g = r.grid;
  const int nu = std::max(1, g.nu), nv = std::max(1, g.nv);
  const int cell = std::max(1, kPlotTargetPx / std::max(nu, nv));
  const int plot_w = cell * nu, plot_h = cell * nv;
  const int width = kMargin + plot_w + kMargin + kLegendW;
  const int height = kTitleH + std::max(plot_h, 200) + kMargin;

  // Normalised values, one pixel per cell, v up (row 0 of the image is the last grid row).
  OIIO::ImageBuf values(OIIO::ImageSpec(nu, nv, 1, OIIO::TypeDesc::FLOAT));
  const double span = scale.max - scale.min;
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const size_t k = static_cast<size_t>(j) * nu + i;
      const float t = k < r.E.size() ? static_cast<float>(std::clamp((r.E[k] - scale.min) / span, 0.0, 1.0)) : 0.f;
      values.setpixel(i, nv - 1 - j, &t);
    }
  }
  OIIO::ImageBuf coloured = OIIO::ImageBufAlgo::color_map(values, 0, "viridis");
  OIIO::ImageBuf big = OIIO::ImageBufAlgo::resample(coloured, false, OIIO::ROI(0, plot_w, 0, plot_h, 0, 1, 0, 3));
  // Points left out (inside obstacles) are drawn mid grey.
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const size_t k = static_cast<size_t>(j) * nu + i;
      if (k < g.active.size() && !g.active[k]) {
        const float grey[3] = {0.5f, 0.5f, 0.5f};
        OIIO::ImageBufAlgo::fill(big, grey, OIIO::ROI(i * cell, (i + 1) * cell, (nv - 1 - j) * cell, (nv - j) * cell, 0, 1, 0, 3));
      }
    }
  }

  OIIO::ImageBuf canvas(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
  const float white[3] = {1, 1, 1};
  OIIO::ImageBufAlgo::fill(canvas, white);
  OIIO::ImageBufAlgo::paste(canvas, kMargin, kTitleH, 0, 0, big);

  // Legend bar: top = scale.max.
  const int bar_x = kMargin + plot_w + kMargin, bar_h = std::max(plot_h, 200);
  OIIO::ImageBuf ramp(OIIO::ImageSpec(1, bar_h, 1, OIIO::TypeDesc::FLOAT));
  for (int y = 0; y < bar_h; ++y) {
    const float t = 1.0f - (y + 0.5f) / bar_h;
    ramp.setpixel(0, y, &t);
  }
  OIIO::ImageBuf ramp_rgb = OIIO::ImageBufAlgo::color_map(ramp, 0, "viridis");
  OIIO::ImageBuf bar = OIIO::ImageBufAlgo::resample(ramp_rgb, false, OIIO::ROI(0, kBarW, 0, bar_h, 0, 1, 0, 3));
  OIIO::ImageBufAlgo::paste(canvas, bar_x, kTitleH, 0, 0, bar);

  std::string warning;
  const float black[3] = {0, 0, 0};
  auto text = [&](int x, int y, const std::string& s, int px) {
    if (!warning.empty()) return;
    if (!OIIO::ImageBufAlgo::render_text(canvas, x, y, s, px, kFont, black)) {
      warning = path.filename().string() + ": plot written without labels (font " + kFont +
                " unavailable: install fonts-dejavu-core)";
    }
  };
  // Isolux lines: light lines on the dark half of the map, dark lines on the light half, so
  // each stays visible in colour and in grey print; one label per level on a white box.
  if (overlay.isolux && g.kind == geometry::SurfaceGrid::Kind::grid) {
    for (double level : isolux_levels(scale, r.stats.Emin, r.stats.Emax)) {
      const auto segments = isolux_segments(r.E, nu, nv, level, g.active);
      if (segments.empty()) continue;
      const bool dark_map = (level - scale.min) / span < 0.55;
      const float line_colour[3] = {dark_map ? 1.0f : 0.1f, dark_map ? 1.0f : 0.1f, dark_map ? 1.0f : 0.1f};
      auto px = [&](double x) { return kMargin + static_cast<int>(std::lround((x + 0.5) * cell)); };
      auto py = [&](double y) { return kTitleH + static_cast<int>(std::lround((nv - 1 - y + 0.5) * cell)); };
      for (const auto& sg : segments) {
        OIIO::ImageBufAlgo::render_line(canvas, px(sg.x0), py(sg.y0), px(sg.x1), py(sg.y1), line_colour);
      }
      const auto& mid = segments[segments.size() / 2];
      const std::string label = format_lux(level);
      const int lx = (px(mid.x0) + px(mid.x1)) / 2, ly = (py(mid.y0) + py(mid.y1)) / 2;
      const int w = static_cast<int>(label.size()) * 7 + 4;
      const float white_box[3] = {1, 1, 1};
      OIIO::ImageBufAlgo::fill(canvas, white_box, OIIO::ROI(lx - w / 2, lx + w / 2 + 1, ly - 7, ly + 6, 0, 1, 0, 3));
      text(lx - w / 2 + 2, ly + 4, label, 11);
    }
  }
  // Luminaires: a white square with a black outline and centre dot at each position.
  for (const Vec3& p : overlay.luminaires) {
    double fx = 0.0, fy = 0.0;
    if (!plot_position(g, p, fx, fy)) continue;
    const int x = kMargin + static_cast<int>(std::lround(fx * plot_w));
    const int y = kTitleH + static_cast<int>(std::lround(fy * plot_h));
    const float white_fill[3] = {1, 1, 1}, outline[3] = {0, 0, 0};
    OIIO::ImageBufAlgo::render_box(canvas, x - 5, y - 5, x + 5, y + 5, white_fill, true);
    OIIO::ImageBufAlgo::render_box(canvas, x - 5, y - 5, x + 5, y + 5, outline, false);
    OIIO::ImageBufAlgo::render_box(canvas, x - 1, y - 1, x + 1, y + 1, outline, true);
  }
  for (double tick : scale.ticks) {
    const int y = kTitleH + static_cast<int>(std::lround((1.0 - (tick - scale.min) / span) * (bar_h - 1)));
    const float tick_colour[3] = {0, 0, 0};
    OIIO::ImageBufAlgo::fill(canvas, tick_colour, OIIO::ROI(bar_x + kBarW, bar_x + kBarW + 6, y, y + 1, 0, 1, 0, 3));
    text(bar_x + kBarW + 10, y + kFontPx / 2 - 1, format_lux(tick) + " lx", kFontPx);
  }
  char stats[200];
  std::snprintf(stats, sizeof stats, "Emin %.4g  Eavg %.4g  Emax %.4g lx   U0 %.2f   %d x %d points",
                r.stats.Emin, r.stats.Eavg, r.stats.Emax, r.stats.U0, g.nu, g.nv);
  text(kMargin, 22, g.name, 18);
  text(kMargin, 44, stats, 13);

  OIIO::ImageBuf out = OIIO::ImageBufAlgo::copy(canvas, OIIO::TypeDesc::UINT8);
  if (!out.write(path.string())) {
    throw CalculationError(path.string() + ": cannot write the image: " + out.geterror());
  }
  return warning;
}

}  // namespace luxgrid::report
