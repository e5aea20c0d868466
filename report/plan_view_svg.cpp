#include "report/plan_view_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "calc/opening_placement.h"
#include "report/colour_scale.h"
#include "report/html_text.h"
#include "report/luminaire_outline.h"
#include "util/format.h"

namespace luxgrid::report {

namespace {

// 0.7 ~ cos 45 deg: a normal within 45 degrees of vertical makes a horizontal grid (drawn as its
// outline); others are vertical (drawn as a line along their foot).
constexpr double kHorizontalNormalZ = 0.7;

}  // namespace

std::string plan_view_svg(const calc::Room& room, const std::vector<calc::Luminaire>& luminaires,
                          const std::vector<geometry::SurfaceGrid>& surfaces, int width_px,
                          const std::vector<calc::DaylightOpening>& openings,
                          double north_angle_deg) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const auto& p : room.outline) {
    x0 = std::min(x0, p.x);
    y0 = std::min(y0, p.y);
    x1 = std::max(x1, p.x);
    y1 = std::max(y1, p.y);
  }
  if (room.outline.empty()) {
    x0 = y0 = 0.0;
    x1 = y1 = 1.0;
  }
  const double w_m = std::max(x1 - x0, 1e-3), h_m = std::max(y1 - y0, 1e-3);
  // px around the room for wall numbers, the north arrow and the scale bar
  constexpr double kPad = 40.0;
  const double scale = (width_px - 2 * kPad) / w_m;  // px per metre
  const int height_px = static_cast<int>(std::ceil(h_m * scale + 2 * kPad + 20));
  auto sx = [&](double x) { return kPad + (x - x0) * scale; };
  auto sy = [&](double y) { return kPad + (y1 - y) * scale; };
  auto inside_box = [&](double x, double y, double slack) {
    return x >= x0 - slack && x <= x1 + slack && y >= y0 - slack && y <= y1 + slack;
  };

  char buf[4096];
  std::string svg;
  std::snprintf(buf, sizeof buf,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"plan\" width=\"%d\" "
                "height=\"%d\" viewBox=\"0 0 %d %d\" "
                "font-family='%s' font-size=\"11\"><title>Plan of %s</title>",
                width_px, height_px, width_px, height_px, kReportFontFamily,
                html_escape(room.name).c_str());
  svg += buf;
  // An SVG polygon's points: each corner's (x, y) in pixels.
  const auto points = [&](const auto& corners) {
    std::string out;
    for (const auto& q : corners) {
      std::snprintf(buf, sizeof buf, "%.1f,%.1f ", sx(q.x), sy(q.y));
      out += buf;
    }
    return out;
  };
  svg += "<polygon class=\"room\" points=\"" + points(room.outline) +
         "\" fill=\"#f4f4f0\" stroke=\"#222\" stroke-width=\"2.5\"/>";

  // Wall numbers outside each edge, as the wall grids' names use them ("room wall 3" is edge 3,
  // from corner 3 to corner 4 of the outline).
  const size_t n = room.outline.size();
  for (size_t k = 0; k < n; ++k) {
    const Vec2 a = room.outline[k], b = room.outline[(k + 1) % n];
    const Vec2 d = b - a;
    const double len = glm::length(d);
    if (!(len > 0)) continue;
    const Vec2 out(d.y / len, -d.x / len);  // outward normal of a counter-clockwise outline
    const Vec2 m = (a + b) * 0.5;
    std::snprintf(
        buf, sizeof buf,
        "<text class=\"wall-number\" x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" fill=\"#555\" "
        "font-size=\"10\">wall %zu</text>",
        sx(m.x) + out.x * 14, sy(m.y) - out.y * 14 + 4, k);
    svg += buf;
  }

  // Obstacles: their footprint, grey, with name and height in the tooltip; drawn before the grids
  // and luminaires so those stay on top.
  for (const auto& o : room.obstacles) {
    const std::string fp = points(o.footprint);
    std::snprintf(buf, sizeof buf, "%.2f to %.2f m", o.z0, o.z1);
    svg += "<polygon class=\"obstacle\" points=\"" + fp +
           "\" fill=\"#b8b8b8\" stroke=\"#555\" stroke-width=\"1.2\"><title>obstacle " +
           html_escape(o.name) + ", " + buf + "</title></polygon>";
  }

  // Daylight openings, before the grids and luminaires: a window as the stretch of its wall it
  // takes (its corners' extent along the wall), a roof light as its outline.
  for (const auto& o : openings) {
    const std::string title =
        "<title>" + html_escape(o.name) + ": " +
        (o.glazing_transmittance
             ? "glazed, transmittance " + format_double("%.2f", *o.glazing_transmittance)
             : std::string("unglazed")) +
        "</title>";
    if (o.face.kind == calc::RoomFaceRef::Kind::wall) {
      const Vec2 a = room.outline[o.face.wall], b = room.outline[(o.face.wall + 1) % n];
      double s0 = 1e300, s1 = -1e300;
      for (const Vec2& q : calc::face_coordinates(room, o.face, o.polygon))
        s0 = std::min(s0, q.x), s1 = std::max(s1, q.x);
      const Vec2 along = (b - a) / glm::length(b - a), p0 = a + along * s0, p1 = a + along * s1;
      std::snprintf(buf, sizeof buf,
                    "<line class=\"daylight-opening\" data-opening=\"%s\" x1=\"%.1f\" "
                    "y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#3b8fd9\" stroke-width=\"6\">",
                    html_escape(o.name).c_str(), sx(p0.x), sy(p0.y), sx(p1.x), sy(p1.y));
      svg += buf + title + "</line>";
    } else {
      svg += "<polygon class=\"daylight-opening\" data-opening=\"" + html_escape(o.name) +
             "\" points=\"" + points(o.polygon) +
             "\" fill=\"#3b8fd9\" fill-opacity=\"0.15\" stroke=\"#3b8fd9\" stroke-width=\"2\" "
             "stroke-dasharray=\"6 3\">" +
             title + "</polygon>";
    }
  }

  // Calculation surfaces: horizontal grids as their real outline (an L-shaped workplane as an L)
  // dashed green; vertical grids as a green band along their foot; points as crosses; observers
  // as eyes with their view directions.
  for (const auto& g : surfaces) {
    if (g.kind == geometry::SurfaceGrid::Kind::grid) {
      const Vec3 a = g.origin, b = g.origin + g.u_dir * g.size_u, cc = b + g.v_dir * g.size_v,
                 d = g.origin + g.v_dir * g.size_v;
      const double mx = (a.x + cc.x) / 2, my = (a.y + cc.y) / 2;
      if (!inside_box(mx, my, 0.01)) continue;
      const Vec3 normal = glm::cross(g.u_dir, g.v_dir);
      if (std::abs(normal.z) >= kHorizontalNormalZ) {
        if (normal.z < 0) continue;  // ceilings lie over the floor: the floor's outline shows both
        std::vector<std::vector<Vec2>> outline = g.region;
        if (outline.empty()) outline.push_back({Vec2(a), Vec2(b), Vec2(cc), Vec2(d)});
        for (const auto& poly : outline) {
          svg += "<polygon class=\"surface\" data-surface=\"" + html_escape(g.name) +
                 "\" points=\"" + points(poly) +
                 "\" fill=\"none\" stroke=\"#2a7f62\" stroke-width=\"1.2\" stroke-dasharray=\"5 "
                 "3\"><title>" +
                 html_escape(g.name) + ": " + std::to_string(g.nu) + " x " + std::to_string(g.nv) +
                 " points</title></polygon>";
        }
      } else {
        // A vertical grid: its foot from a to b, drawn 4 px inside the room (towards its normal).
        const Vec2 in = glm::length(Vec2(normal)) > 0 ? glm::normalize(Vec2(normal)) : Vec2(0.0);
        const Vec3 foot0 = g.v_dir.z >= 0 ? a : d, foot1 = g.v_dir.z >= 0 ? b : cc;
        std::snprintf(buf, sizeof buf,
                      "<line class=\"wall-grid\" data-surface=\"%s\" x1=\"%.1f\" y1=\"%.1f\" "
                      "x2=\"%.1f\" y2=\"%.1f\" "
                      "stroke=\"#2a7f62\" stroke-width=\"3\" stroke-opacity=\"0.7\"><title>%s: %d "
                      "x %d points</title></line>",
                      html_escape(g.name).c_str(), sx(foot0.x) + in.x * 4, sy(foot0.y) - in.y * 4,
                      sx(foot1.x) + in.x * 4, sy(foot1.y) - in.y * 4, html_escape(g.name).c_str(),
                      g.nu, g.nv);
        svg += buf;
      }
    } else {
      const bool eyes = g.kind == geometry::SurfaceGrid::Kind::observers;
      for (size_t k = 0; k < g.points.size(); ++k) {
        const Vec3 p = g.points[k];
        if (!inside_box(p.x, p.y, 0.01)) continue;
        if (eyes) {
          const Vec3 dir = k < g.normals.size() ? g.normals[k] : Vec3(0.0);
          const double h = std::hypot(dir.x, dir.y);
          std::snprintf(buf, sizeof buf,
                        "<g class=\"observer\" data-surface=\"%s\"><circle cx=\"%.1f\" cy=\"%.1f\" "
                        "r=\"3.5\" fill=\"#fff\" "
                        "stroke=\"#6a3d9a\" stroke-width=\"1.4\"/><line x1=\"%.1f\" y1=\"%.1f\" "
                        "x2=\"%.1f\" y2=\"%.1f\" "
                        "stroke=\"#6a3d9a\" stroke-width=\"1.2\"/></g>",
                        html_escape(g.name).c_str(), sx(p.x), sy(p.y), sx(p.x), sy(p.y),
                        sx(p.x) + (h > 0 ? dir.x / h * 14 : 0),
                        sy(p.y) - (h > 0 ? dir.y / h * 14 : 0));
        } else {
          std::snprintf(
              buf, sizeof buf,
              "<g class=\"probe\" data-surface=\"%s\"><title>%s point %zu at %.2f, %.2f, %.2f "
              "m</title>"
              "<path d=\"M%.1f %.1fl8 8m0 -8l-8 8\" stroke=\"#b03a2e\" stroke-width=\"2\"/>"
              "<text x=\"%.1f\" y=\"%.1f\" font-size=\"9\" fill=\"#b03a2e\">P%zu</text></g>",
              html_escape(g.name).c_str(), html_escape(g.name).c_str(), k + 1, p.x, p.y, p.z,
              sx(p.x) - 4, sy(p.y) - 4, sx(p.x) + 6, sy(p.y) + 12, k + 1);
        }
        svg += buf;
      }
    }
  }
  // Luminaires: the luminous opening to scale (a small circle for a point source), a bar along
  // C0 (local +x) through it, a red line along the aiming direction (local -z) when tilted, and
  // the number the luminaire table uses (its place in the project's list, from 1).
  for (size_t index = 0; index < luminaires.size(); ++index) {
    const auto& l = luminaires[index];
    const int number = static_cast<int>(index) + 1;
    const Vec3 p = l.pose.position;
    if (!inside_box(p.x, p.y, 0.5)) continue;
    const Vec3 aim = l.pose.rotation * Vec3(0, 0, -1);
    const Vec3 c0 = l.pose.rotation * Vec3(1, 0, 0);
    std::snprintf(buf, sizeof buf,
                  "<g class=\"luminaire\" data-number=\"%d\"><title>%d: %s (%s) at %.2f, %.2f, "
                  "%.2f m</title>",
                  number, number, html_escape(l.label).c_str(), html_escape(l.photometry).c_str(),
                  p.x, p.y, p.z);
    svg += buf;
    const auto outline = luminous_outline(l);
    double half_c0_px = 7.0;  // the C0 bar reaches past the opening by half its length
    if (outline.size() >= 3) {
      svg += "<polygon class=\"opening\" points=\"" + points(outline) +
             "\" fill=\"#ffd34d\" stroke=\"#222\" stroke-width=\"1\"/>";
      half_c0_px = std::max(half_c0_px, l.opening.length / 2 * scale);
    } else {
      std::snprintf(buf, sizeof buf,
                    "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"5\" fill=\"#ffd34d\" stroke=\"#222\" "
                    "stroke-width=\"1\"/>",
                    sx(p.x), sy(p.y));
      svg += buf;
    }
    const double hc = std::hypot(c0.x, c0.y);
    if (hc > 0.02) {
      const double bar = half_c0_px + 6.0;
      std::snprintf(buf, sizeof buf,
                    "<line class=\"c0\" x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" "
                    "stroke=\"#1f3f8f\" stroke-width=\"1.4\"/>",
                    sx(p.x), sy(p.y), sx(p.x) + c0.x / hc * bar, sy(p.y) - c0.y / hc * bar);
      svg += buf;
    }
    const double tilt = std::hypot(aim.x, aim.y);
    if (tilt > 0.02) {  // tilted more than ~1 degree: show where it points
      const double len = 18.0 + 30.0 * tilt;
      std::snprintf(buf, sizeof buf,
                    "<line class=\"aim\" x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" "
                    "stroke=\"#c0392b\" stroke-width=\"2\"/>",
                    sx(p.x), sy(p.y), sx(p.x) + aim.x / tilt * len, sy(p.y) - aim.y / tilt * len);
      svg += buf;
    }
    // The number just above the opening's top edge.
    double top_px = sy(p.y) - 5;
    for (const Vec3& q : outline) top_px = std::min(top_px, sy(q.y));
    std::snprintf(buf, sizeof buf,
                  "<text x=\"%.1f\" y=\"%.1f\" font-size=\"10\" font-weight=\"bold\" "
                  "text-anchor=\"middle\">%d</text></g>",
                  sx(p.x), top_px - 3, number);
    svg += buf;
  }
  // North arrow (top right) and a scale bar of a round length (bottom left). The arrow turns
  // about its middle to true north: clockwise on the page, as the north angle is in the plan
  // (SVG's y runs down, so its positive rotation is clockwise too).
  const double nx = width_px - 20.0, ny = 10.0;
  std::string turn;
  if (north_angle_deg != 0.0) {
    std::snprintf(buf, sizeof buf, " transform=\"rotate(%.1f %.1f %.1f)\"", north_angle_deg, nx,
                  ny + 15);
    turn = buf;
  }
  std::snprintf(
      buf, sizeof buf,
      "<g class=\"north\"%s><polygon points=\"%.1f,%.1f %.1f,%.1f %.1f,%.1f\" fill=\"#222\"/>"
      "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" font-weight=\"bold\">N</text></g>",
      turn.c_str(), nx, ny, nx - 6, ny + 18, nx + 6, ny + 18, nx, ny + 30);
  svg += buf;
  double bar_m = nice_ceil(w_m / 5.0);
  if (bar_m * scale > width_px / 2.0) bar_m /= 2.0;
  const double bx = kPad, by = height_px - 14.0;
  std::snprintf(buf, sizeof buf,
                "<g class=\"scalebar\"><rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"5\" "
                "fill=\"#222\"/>"
                "<text x=\"%.1f\" y=\"%.1f\">%g m</text></g></svg>",
                bx, by, bar_m * scale, bx + bar_m * scale + 6, by + 6, bar_m);
  svg += buf;
  return svg;
}

}  // namespace luxgrid::report
