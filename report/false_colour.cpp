#include "report/false_colour.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "report/isolux.h"
#include "report/png_file.h"
#include "report/raster.h"
#include "report/raster_text.h"
#include "report/viridis.h"

namespace luxgrid::report {

namespace {

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
  const Rgb white{1, 1, 1}, black{0, 0, 0};
  Raster canvas(width, height, white);

  // One square of cell x cell pixels per grid point, v up (the top row is the last grid row);
  // points left out (inside obstacles) are drawn mid grey.
  const double span = scale.max - scale.min;
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const size_t k = static_cast<size_t>(j) * nu + i;
      const bool inactive = k < g.active.size() && !g.active[k];
      const double t = k < r.E.size() ? std::clamp((r.E[k] - scale.min) / span, 0.0, 1.0) : 0.0;
      const int x = kMargin + i * cell, y = kTitleH + (nv - 1 - j) * cell;
      canvas.fill(x, x + cell, y, y + cell, inactive ? Rgb{0.5f, 0.5f, 0.5f} : viridis(t));
    }
  }

  // Legend bar: top = scale.max, each row the colour at its centre.
  const int bar_x = kMargin + plot_w + kMargin, bar_h = std::max(plot_h, 200);
  for (int y = 0; y < bar_h; ++y) canvas.fill(bar_x, bar_x + kBarW, kTitleH + y, kTitleH + y + 1, viridis(1.0 - (y + 0.5) / bar_h));

  std::string warning;
  auto text = [&](int x, int y, const std::string& s, int px) {
    if (!warning.empty()) return;
    if (!draw_text(canvas, x, y, s, px, kPlotFont, black)) {
      warning = path.filename().string() + ": plot written without labels (font " + kPlotFont +
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
      const float shade = dark_map ? 1.0f : 0.1f;
      const Rgb line_colour{shade, shade, shade};
      auto px = [&](double x) { return kMargin + static_cast<int>(std::lround((x + 0.5) * cell)); };
      auto py = [&](double y) { return kTitleH + static_cast<int>(std::lround((nv - 1 - y + 0.5) * cell)); };
      for (const auto& sg : segments) canvas.line(px(sg.x0), py(sg.y0), px(sg.x1), py(sg.y1), line_colour);
      const auto& mid = segments[segments.size() / 2];
      const std::string label = format_lux(level);
      const int lx = (px(mid.x0) + px(mid.x1)) / 2, ly = (py(mid.y0) + py(mid.y1)) / 2;
      const int w = static_cast<int>(label.size()) * 7 + 4;
      canvas.fill(lx - w / 2, lx + w / 2 + 1, ly - 7, ly + 6, white);
      text(lx - w / 2 + 2, ly + 4, label, 11);
    }
  }
  // Luminaires: a white square with a black outline and centre dot at each position.
  for (const Vec3& p : overlay.luminaires) {
    double fx = 0.0, fy = 0.0;
    if (!plot_position(g, p, fx, fy)) continue;
    const int x = kMargin + static_cast<int>(std::lround(fx * plot_w));
    const int y = kTitleH + static_cast<int>(std::lround(fy * plot_h));
    canvas.box(x - 5, y - 5, x + 5, y + 5, white, true);
    canvas.box(x - 5, y - 5, x + 5, y + 5, black, false);
    canvas.box(x - 1, y - 1, x + 1, y + 1, black, true);
  }
  for (double tick : scale.ticks) {
    const int y = kTitleH + static_cast<int>(std::lround((1.0 - (tick - scale.min) / span) * (bar_h - 1)));
    canvas.fill(bar_x + kBarW, bar_x + kBarW + 6, y, y + 1, black);
    text(bar_x + kBarW + 10, y + kFontPx / 2 - 1, format_lux(tick) + " lx", kFontPx);
  }
  char stats[200];
  std::snprintf(stats, sizeof stats, "Emin %.4g  Eavg %.4g  Emax %.4g lx   U0 %.2f   %d x %d points",
                r.stats.Emin, r.stats.Eavg, r.stats.Emax, r.stats.U0, g.nu, g.nv);
  text(kMargin, 22, g.name, 18);
  text(kMargin, 44, stats, 13);

  write_png(canvas, path);
  return warning;
}

}  // namespace luxgrid::report
