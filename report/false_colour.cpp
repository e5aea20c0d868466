#include "report/false_colour.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>

#include "geometry/polygon.h"
#include "report/isolux.h"
#include "report/luminaire_outline.h"
#include "report/map_frame.h"
#include "report/map_samples.h"
#include "report/png_file.h"
#include "report/raster.h"
#include "report/raster_text.h"
#include "report/viridis.h"

namespace luxgrid::report {

namespace {

// Layout in pixels. The map is drawn to scale: its longer side at most kMapMaxW wide or kMapMaxH
// tall, whichever binds first.
constexpr double kMapMaxW = 560.0, kMapMaxH = 400.0;
constexpr int kTop = 92, kLeft = 58, kBottom = 44, kLegendGap = 22, kBarW = 20, kLegendTextW = 96,
              kMinWidth = 640;
constexpr int kTitlePx = 17, kStatsPx = 13, kNotePx = 12, kAxisPx = 12, kLabelPx = 12;

const Rgb kWhite{1, 1, 1}, kBlack{0, 0, 0};

std::string format_lux(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, v >= 100 || v == std::floor(v) ? "%.0f" : "%.1f", v);
  return buf;
}

std::string format_m(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", std::abs(v) < 1e-9 ? 0.0 : v);
  return buf;
}

struct Box {
  int x0, y0, x1, y1;
  bool overlaps(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

// A map's size and scale, from the grid and the scene alone.
MapLayout plot_map_layout(const geometry::SurfaceGrid& g, const calc::Scene* scene) {
  return map_layout(g, scene, kMapMaxW, kMapMaxH);
}

}  // namespace

std::vector<PlotLevel> plot_levels(const PlotOverlay& overlay, const ColourScale& scale, double min,
                                   double max) {
  std::vector<PlotLevel> levels;
  for (double v : overlay.required_lx)
    if (v > min && v < max) levels.push_back({v, true});
  std::vector<double> values;
  if (overlay.levels.empty()) {
    values = isolux_levels(scale, min, max);
  } else {
    for (double v : overlay.levels)
      if (v > min && v < max) values.push_back(v);
  }
  for (double v : values) {
    bool dup = false;
    for (const PlotLevel& l : levels) dup = dup || std::abs(l.value - v) < 1e-9 * std::max(1.0, v);
    if (!dup) levels.push_back({v, false});
  }
  return levels;
}

std::string write_false_colour_png(const calc::SurfaceResult& r, const ColourScale& scale,
                                   const std::filesystem::path& path) {
  return write_false_colour_png(r, scale, path, PlotOverlay{});
}

std::shared_ptr<const MapSamples> map_samples(const calc::SurfaceResult& r,
                                              const calc::Scene* scene) {
  const MapLayout layout = plot_map_layout(r.grid, scene);
  return std::make_shared<const MapSamples>(
      make_map_samples(r, scene, layout, cut_obstacles(layout), Field(r)));
}

std::string write_false_colour_png(const calc::SurfaceResult& r, const ColourScale& scale,
                                   const std::filesystem::path& path, const PlotOverlay& overlay,
                                   MapPixels* where, const MapSamples* samples, std::string* png) {
  const auto& g = r.grid;
  const MapLayout layout = plot_map_layout(g, overlay.scene);
  const MapFrame& frame = layout.frame;
  const bool horizontal = layout.horizontal;
  const double ppm = layout.ppm;
  const int map_w = layout.map_w, map_h = layout.map_h;
  const int bar_h = std::max(map_h, 160);
  const int width = std::max(kMinWidth, kLeft + map_w + kLegendGap + kBarW + kLegendTextW);
  const int height = kTop + std::max(map_h, bar_h) + kBottom;
  Raster canvas(width, height, kWhite);
  if (where) *where = MapPixels{kLeft, kTop, map_w, map_h, ppm};
  // World point -> pixel (x right, y down) and back.
  auto to_px = [&](const Vec3& w, double& x, double& y) {
    double a = 0, b = 0;
    frame_coords(frame, w, a, b);
    x = kLeft + a * ppm, y = kTop + map_h - b * ppm;
  };
  auto line_world = [&](const Vec3& p, const Vec3& q, Rgb c, int thickness) {
    double x0, y0, x1, y1;
    to_px(p, x0, y0), to_px(q, x1, y1);
    for (int t = 0; t < thickness; ++t) {
      const int o = t - thickness / 2;
      const bool steep = std::abs(y1 - y0) > std::abs(x1 - x0);
      canvas.line(int(std::lround(x0)) + (steep ? o : 0), int(std::lround(y0)) + (steep ? 0 : o),
                  int(std::lround(x1)) + (steep ? o : 0), int(std::lround(y1)) + (steep ? 0 : o),
                  c);
    }
  };
  auto polygon_plan = [&](const std::vector<Vec2>& poly, double z, Rgb c, int thickness) {
    for (size_t k = 0; k < poly.size(); ++k) {
      const Vec2 a = poly[k], b = poly[(k + 1) % poly.size()];
      line_world({a.x, a.y, z}, {b.x, b.y, z}, c, thickness);
    }
  };

  // --- the map: each pixel as the samples say (made here unless given for this grid) -----------
  const Field field(r);
  const double span = scale.max - scale.min;
  const double su = g.nu > 0 ? g.size_u / g.nu : 1.0,
               sv = g.nv > 0 ? g.size_v / g.nv : 1.0;  // cell size, m
  const bool reuse = samples && samples->scene == overlay.scene && samples->map_w == map_w &&
                     samples->map_h == map_h && samples->points == r.E.size() &&
                     samples->active == g.active;
  MapSamples made;
  if (!reuse) made = make_map_samples(r, overlay.scene, layout, cut_obstacles(layout), field);
  paint_map(reuse ? *samples : made, field, r.E, scale, canvas, kLeft, kTop);

  // --- outlines: the room and its obstacles (plans), the surface's own outline -----------------
  const double z = frame.origin.z;
  if (horizontal && frame.room) {
    for (const auto& o : frame.room->obstacles) {
      if (o.z0 <= z && z <= o.z1) polygon_plan(o.footprint, z, Rgb{0.3f, 0.3f, 0.3f}, 1);
    }
  }
  if (!g.region.empty()) {
    for (const auto& poly : g.region) polygon_plan(poly, z, Rgb{0.15f, 0.15f, 0.15f}, 1);
  }
  if (horizontal && frame.room) {
    polygon_plan(frame.room->outline, z, kBlack, 3);
  } else {
    canvas.box(kLeft, kTop, kLeft + map_w - 1, kTop + map_h - 1, kBlack, false);
  }

  std::string warning;
  auto text = [&](int x, int y, const std::string& s, int px, Rgb colour = kBlack) {
    if (!warning.empty()) return;
    if (!draw_text(canvas, x, y, s, px, kPlotFont, colour)) {
      warning = path.filename().string() + ": plot written without labels (font " + kPlotFont +
                " unavailable: install fonts-dejavu-core)";
    }
  };
  std::vector<Box> taken;  // label boxes and luminaire marks, so no label covers another

  // --- luminaires over plans: their luminous opening to scale, white with a black edge ----------
  if (horizontal && overlay.scene) {
    for (const auto& l : overlay.scene->luminaires) {
      double cx, cy;
      to_px({l.pose.position.x, l.pose.position.y, z}, cx, cy);
      if (cx < kLeft || cx > kLeft + map_w || cy < kTop || cy > kTop + map_h) continue;
      auto outline = luminous_outline(l);
      double x0 = cx, y0 = cy, x1 = cx, y1 = cy;
      if (outline.size() >= 3) {
        std::vector<Vec2> plan;
        for (const Vec3& p : outline) plan.emplace_back(p.x, p.y);
        polygon_plan(plan, z, kBlack, 1);
        for (const Vec3& p : outline) {
          double x, y;
          to_px({p.x, p.y, z}, x, y);
          x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
        }
      }
      const int ix = int(std::lround(cx)), iy = int(std::lround(cy));
      canvas.box(ix - 3, iy - 3, ix + 3, iy + 3, kWhite, true);
      canvas.box(ix - 3, iy - 3, ix + 3, iy + 3, kBlack, false);
      taken.push_back({int(x0) - 2, int(y0) - 2, int(x1) + 3, int(y1) + 3});
    }
  }

  // --- isolux lines: round values and each requirement; labels placed where they fit -----------
  if (overlay.isolux && g.kind == geometry::SurfaceGrid::Kind::grid && g.nu >= 2 && g.nv >= 2) {
    // The field as the map shows it sampled S times finer than the grid, over the whole
    // rectangle (the outermost half cells hold the edge values), so the contours follow the
    // colours (curves within a cell) and run to the surface's edge instead of stopping at the
    // outermost points. Fine sample (i, j) sits at grid index coordinates (i / S - 0.5, j / S -
    // 0.5).
    const double cell_px = std::min(su, sv) * ppm;
    const int S = std::clamp(static_cast<int>(cell_px / 4.0), 1, 8);
    const int fu = g.nu * S + 1, fv = g.nv * S + 1;
    std::vector<double> fine(static_cast<size_t>(fu) * fv);
    std::vector<bool> fine_on(fine.size());
    // field.sample(i / S - 0.5, j / S - 0.5), its places along u and v found once per column and
    // row.
    std::vector<AxisStencil> fine_columns(static_cast<size_t>(fu));
    for (int i = 0; i < fu; ++i) fine_columns[i] = Field::axis(double(i) / S - 0.5, field.nu());
    for (int j = 0; j < fv; ++j) {
      const AxisStencil row = Field::axis(double(j) / S - 0.5, field.nv());
      for (int i = 0; i < fu; ++i) {
        const double e = field.value(field.stencil(fine_columns[i], row), r.E);
        fine[static_cast<size_t>(j) * fu + i] = std::isnan(e) ? 0.0 : e;
        fine_on[static_cast<size_t>(j) * fu + i] = !std::isnan(e);
      }
    }
    const bool fixed_levels = !overlay.levels.empty();
    const std::vector<PlotLevel> levels = plot_levels(overlay, scale, r.stats.Emin, r.stats.Emax);
    auto grid_world = [&](double x, double y) {
      return g.origin + g.u_dir * (x / S * su) + g.v_dir * (y / S * sv);
    };
    struct Pending {
      PlotLevel level;
      std::vector<IsoSegment> segments;
    };
    std::vector<Pending> drawn;
    std::vector<double> level_lx;
    for (const PlotLevel& level : levels) level_lx.push_back(level.value);
    auto segments_per_level = isolux_segments(fine, fu, fv, level_lx, fine_on);
    for (size_t k = 0; k < levels.size(); ++k) {
      const PlotLevel& level = levels[k];
      auto& segments = segments_per_level[k];
      if (segments.empty()) continue;
      // Light lines on the dark half of the map, dark lines on the light half: visible in colour
      // and in grey print. Requirement lines are drawn 3 px wide, round values 1 px.
      const float shade = (level.value - scale.min) / span < 0.55 ? 1.0f : 0.08f;
      for (const auto& sg : segments)
        line_world(grid_world(sg.x0, sg.y0), grid_world(sg.x1, sg.y1), Rgb{shade, shade, shade},
                   level.required ? 3 : 1);
      drawn.push_back({level, std::move(segments)});
    }
    // Labels: requirement lines first; for each level the first candidate position along its
    // line (from the middle outwards) whose box is inside the map and free.
    for (const auto& p : drawn) {
      const std::string label =
          format_lux(p.level.value) + (p.level.required ? " " + overlay.unit + " required"
                                       : fixed_levels   ? " " + overlay.unit
                                                        : "");
      const int tw = text_width(label, kLabelPx, kPlotFont) + 6, th = kLabelPx + 4;
      const size_t n = p.segments.size();
      for (size_t step = 0; step < std::min<size_t>(n, 64); ++step) {
        // 1/2, 1/4, 3/4, 1/8, 3/8, ... of the way along the segment list
        size_t denominator = 2, k = step;
        while (k >= denominator / 2) k -= denominator / 2, denominator *= 2;
        const size_t index = std::min(n - 1, (2 * k + 1) * n / denominator);
        const auto& sg = p.segments[index];
        double x0, y0, x1, y1;
        to_px(grid_world(sg.x0, sg.y0), x0, y0), to_px(grid_world(sg.x1, sg.y1), x1, y1);
        const int cx = int(std::lround((x0 + x1) / 2)), cy = int(std::lround((y0 + y1) / 2));
        const Box b{cx - tw / 2, cy - th / 2, cx - tw / 2 + tw, cy - th / 2 + th};
        if (b.x0 < kLeft || b.y0 < kTop || b.x1 > kLeft + map_w || b.y1 > kTop + map_h) continue;
        bool free = true;
        for (const Box& t : taken) free = free && !b.overlaps(t);
        if (!free) continue;
        canvas.fill(b.x0, b.x1, b.y0, b.y1, kWhite);
        if (p.level.required) canvas.box(b.x0, b.y0, b.x1 - 1, b.y1 - 1, kBlack, false);
        text(b.x0 + 3, b.y1 - 4, label, kLabelPx);
        taken.push_back(b);
        break;
      }
    }
  }

  // --- axes in metres: ticks below and left of the map at a round step -------------------------
  auto axis_step = [&](double extent_m) {
    double step = nice_ceil(extent_m / 8.0);
    while (step * ppm < 40.0) step = nice_ceil(step * 1.0001);  // ticks at least 40 px apart
    return step;
  };
  {
    const double step = axis_step(frame.width_m);
    for (long k = static_cast<long>(std::ceil(frame.axis_x0 / step - 1e-9));
         k * step <= frame.axis_x0 + frame.width_m + 1e-9; ++k) {
      const int x = kLeft + static_cast<int>(std::lround((k * step - frame.axis_x0) * ppm));
      canvas.fill(x, x + 1, kTop + map_h, kTop + map_h + 5, kBlack);
      const std::string s = format_m(k * step);
      text(x - text_width(s, kAxisPx, kPlotFont) / 2, kTop + map_h + 18, s, kAxisPx);
    }
    text(kLeft + map_w / 2 - text_width(frame.x_label, kAxisPx, kPlotFont) / 2, kTop + map_h + 36,
         frame.x_label, kAxisPx);
  }
  {
    const double step = axis_step(frame.height_m);
    for (long k = static_cast<long>(std::ceil(frame.axis_y0 / step - 1e-9));
         k * step <= frame.axis_y0 + frame.height_m + 1e-9; ++k) {
      const int y = kTop + map_h - static_cast<int>(std::lround((k * step - frame.axis_y0) * ppm));
      canvas.fill(kLeft - 5, kLeft, y, y + 1, kBlack);
      const std::string s = format_m(k * step);
      text(kLeft - 8 - text_width(s, kAxisPx, kPlotFont), y + kAxisPx / 2 - 1, s, kAxisPx);
    }
    text(4, kTop - 6, frame.y_label, kAxisPx);
  }

  // --- legend: the colour bar with the scale's ticks and the requirement values ---------------
  const int bar_x = kLeft + map_w + kLegendGap;
  for (int y = 0; y < bar_h; ++y)
    canvas.fill(bar_x, bar_x + kBarW, kTop + y, kTop + y + 1, viridis(1.0 - (y + 0.5) / bar_h));
  canvas.box(bar_x, kTop, bar_x + kBarW - 1, kTop + bar_h - 1, kBlack, false);
  auto bar_y = [&](double lx) {
    return kTop + static_cast<int>(std::lround((1.0 - (lx - scale.min) / span) * (bar_h - 1)));
  };
  for (double tick : scale.ticks) {
    const int y = bar_y(tick);
    canvas.fill(bar_x + kBarW, bar_x + kBarW + 5, y, y + 1, kBlack);
    text(bar_x + kBarW + 8, y + kAxisPx / 2 - 1, format_lux(tick) + " " + overlay.unit, kAxisPx);
  }
  for (double lx : overlay.required_lx) {
    if (lx < scale.min || lx > scale.max) continue;
    const int y = bar_y(lx);
    canvas.fill(bar_x - 4, bar_x + kBarW + 4, y - 1, y + 2, Rgb{0.75f, 0.1f, 0.1f});
  }

  // --- title: name, statistics, the view in words ----------------------------------------------
  char stats[200];
  const char* q = overlay.quantity.c_str();
  std::snprintf(stats, sizeof stats,
                "%smin %.1f  %savg %.1f  %smax %.1f %s   U0 %.2f   %d x %d points", q, r.stats.Emin,
                q, r.stats.Eavg, q, r.stats.Emax, overlay.unit.c_str(), r.stats.U0, g.nu, g.nv);
  text(kLeft, 20, g.name, kTitlePx);
  text(kLeft, 40, stats, kStatsPx);
  // The view in words, wrapped to the picture's width.
  std::string line;
  int line_y = 58;
  auto flush = [&] {
    text(kLeft, line_y, line, kNotePx, Rgb{0.25f, 0.25f, 0.25f});
    line.clear(), line_y += 15;
  };
  for (size_t start = 0; start < frame.description.size();) {
    size_t end = frame.description.find(' ', start);
    if (end == std::string::npos) end = frame.description.size();
    const std::string word = frame.description.substr(start, end - start);
    const std::string candidate = line.empty() ? word : line + " " + word;
    if (!line.empty() && kLeft + text_width(candidate, kNotePx, kPlotFont) > width - 8) flush();
    line = line.empty() ? word : line + " " + word;
    start = end + 1;
  }
  if (!line.empty()) flush();

  std::string bytes = path.empty() ? encode_png(canvas) : write_png(canvas, path);
  if (png) *png = std::move(bytes);
  return warning;
}

}  // namespace luxgrid::report
