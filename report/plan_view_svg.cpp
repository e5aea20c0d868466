#include "report/plan_view_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "report/colour_scale.h"

namespace luxgrid::report {

namespace {

std::string escape(const std::string& s) {
  std::string out;
  for (char ch : s) {
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += ch;
    }
  }
  return out;
}

}  // namespace

std::string plan_view_svg(const calc::Room& room, const std::vector<calc::Luminaire>& luminaires,
                          const std::vector<geometry::SurfaceGrid>& surfaces, int width_px) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const auto& p : room.outline) {
    x0 = std::min(x0, p.x); y0 = std::min(y0, p.y);
    x1 = std::max(x1, p.x); y1 = std::max(y1, p.y);
  }
  if (room.outline.empty()) { x0 = y0 = 0.0; x1 = y1 = 1.0; }
  const double w_m = std::max(x1 - x0, 1e-3), h_m = std::max(y1 - y0, 1e-3);
  constexpr double kPad = 40.0;  // px around the room for the north arrow and the scale bar
  const double scale = (width_px - 2 * kPad) / w_m;  // px per metre
  const int height_px = static_cast<int>(std::ceil(h_m * scale + 2 * kPad + 20));
  auto sx = [&](double x) { return kPad + (x - x0) * scale; };
  auto sy = [&](double y) { return kPad + (y1 - y) * scale; };

  char buf[512];
  std::string svg;
  std::snprintf(buf, sizeof buf,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"plan\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\" "
                "font-family=\"DejaVu Sans, sans-serif\" font-size=\"11\"><title>Plan of %s</title>",
                width_px, height_px, width_px, height_px, escape(room.name).c_str());
  svg += buf;
  std::string pts;
  for (const auto& p : room.outline) {
    std::snprintf(buf, sizeof buf, "%.1f,%.1f ", sx(p.x), sy(p.y));
    pts += buf;
  }
  svg += "<polygon points=\"" + pts + "\" fill=\"#f4f4f0\" stroke=\"#222\" stroke-width=\"2.5\"/>";

  // Obstacles: their footprint, hatched grey, with name and height in the tooltip; drawn before
  // the grids and luminaires so those stay on top.
  for (const auto& o : room.obstacles) {
    std::string fp;
    for (const auto& p : o.footprint) {
      std::snprintf(buf, sizeof buf, "%.1f,%.1f ", sx(p.x), sy(p.y));
      fp += buf;
    }
    std::snprintf(buf, sizeof buf, "%.2f to %.2f m", o.z0, o.z1);
    svg += "<polygon class=\"obstacle\" points=\"" + fp +
           "\" fill=\"#b8b8b8\" stroke=\"#555\" stroke-width=\"1.2\"><title>obstacle " + escape(o.name) +
           ", " + buf + "</title></polygon>";
  }

  // Grid extents: horizontal grids as dashed rectangles, vertical ones as a line along the wall.
  for (const auto& g : surfaces) {
    if (g.kind != geometry::SurfaceGrid::Kind::grid) continue;
    const Vec3 a = g.origin, b = g.origin + g.u_dir * g.size_u, cc = b + g.v_dir * g.size_v,
               d = g.origin + g.v_dir * g.size_v;
    const double mx = (a.x + cc.x) / 2, my = (a.y + cc.y) / 2;
    if (mx < x0 - 0.01 || mx > x1 + 0.01 || my < y0 - 0.01 || my > y1 + 0.01) continue;
    std::snprintf(buf, sizeof buf,
                  "<polygon points=\"%.1f,%.1f %.1f,%.1f %.1f,%.1f %.1f,%.1f\" fill=\"none\" stroke=\"#2a7f62\" "
                  "stroke-width=\"1.2\" stroke-dasharray=\"5 3\"><title>grid %s: %d x %d</title></polygon>",
                  sx(a.x), sy(a.y), sx(b.x), sy(b.y), sx(cc.x), sy(cc.y), sx(d.x), sy(d.y), escape(g.name).c_str(), g.nu, g.nv);
    svg += buf;
  }
  // Luminaires: a circle at the position, a line along the projected aiming direction (local -z)
  // when it is tilted, and a short tick along C0 (local +x).
  int number = 0;
  for (const auto& l : luminaires) {
    const Vec3 p = l.pose.position;
    if (p.x < x0 - 0.5 || p.x > x1 + 0.5 || p.y < y0 - 0.5 || p.y > y1 + 0.5) continue;
    ++number;
    const Vec3 aim = l.pose.rotation * Vec3(0, 0, -1);
    const Vec3 c0 = l.pose.rotation * Vec3(1, 0, 0);
    const double r = 7.0;
    std::snprintf(buf, sizeof buf,
                  "<g class=\"luminaire\"><title>%s (%s) at %.2f, %.2f, %.2f m</title>"
                  "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"#ffd34d\" stroke=\"#222\" stroke-width=\"1.2\"/>"
                  "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#222\" stroke-width=\"1\"/>",
                  escape(l.label).c_str(), escape(l.photometry).c_str(), p.x, p.y, p.z, sx(p.x), sy(p.y), r,
                  sx(p.x) - c0.x * r * 1.6, sy(p.y) + c0.y * r * 1.6, sx(p.x) + c0.x * r * 1.6, sy(p.y) - c0.y * r * 1.6);
    svg += buf;
    const double tilt = std::hypot(aim.x, aim.y);
    if (tilt > 0.02) {  // tilted more than ~1 degree: show where it points
      const double len = 18.0 + 30.0 * tilt;
      std::snprintf(buf, sizeof buf,
                    "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#c0392b\" stroke-width=\"2\"/>",
                    sx(p.x), sy(p.y), sx(p.x) + aim.x / tilt * len, sy(p.y) - aim.y / tilt * len);
      svg += buf;
    }
    std::snprintf(buf, sizeof buf, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"9\">%d</text></g>", sx(p.x) + r + 2,
                  sy(p.y) - r, number);
    svg += buf;
  }
  // North arrow (top right) and a scale bar of a round length (bottom left).
  const double nx = width_px - 20.0, ny = 10.0;
  std::snprintf(buf, sizeof buf,
                "<g class=\"north\"><polygon points=\"%.1f,%.1f %.1f,%.1f %.1f,%.1f\" fill=\"#222\"/>"
                "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" font-weight=\"bold\">N</text></g>",
                nx, ny, nx - 6, ny + 18, nx + 6, ny + 18, nx, ny + 30);
  svg += buf;
  double bar_m = nice_ceil(w_m / 5.0);
  if (bar_m * scale > width_px / 2.0) bar_m /= 2.0;
  const double bx = kPad, by = height_px - 14.0;
  std::snprintf(buf, sizeof buf,
                "<g class=\"scalebar\"><rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"5\" fill=\"#222\"/>"
                "<text x=\"%.1f\" y=\"%.1f\">%g m</text></g></svg>",
                bx, by, bar_m * scale, bx + bar_m * scale + 6, by + 6, bar_m);
  svg += buf;
  return svg;
}

}  // namespace luxgrid::report
