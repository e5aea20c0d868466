#include "photometry/opening.h"

#include <algorithm>
#include <cmath>

#include "photometry/source_text.h"

namespace luxgrid::photometry {

namespace {
using Shape = LuminousOpening::Shape;

LuminousOpening make(Shape s, double length, double width, double height, std::string what) {
  LuminousOpening o;
  o.shape = s;
  o.length = length;
  o.width = width;
  o.height = height;
  o.description = std::move(what);
  return o;
}
}  // namespace

LuminousOpening ies_opening(double w, double l, double h, std::string& warning) {
  warning.clear();
  const bool same_wl = std::abs(std::abs(w) - std::abs(l)) <= 1e-9 * std::max(std::abs(w), 1.0);
  if (w == 0 && l == 0 && h == 0) return make(Shape::point, 0, 0, 0, "point");
  if (w > 0 && l > 0 && h == 0) return make(Shape::rectangle, l, w, 0, "rectangle");
  if (w > 0 && l > 0 && h > 0)
    return make(Shape::rectangle, l, w, h, "rectangle with luminous sides");
  if (w < 0 && l == 0 && h == 0)  // LM-63-1986..1995: round, diameter |width|
    return make(Shape::disk, -w, -w, 0, "round");
  if (w < 0 && l < 0 && h == 0) return make(Shape::disk, -l, -w, 0, same_wl ? "circle" : "ellipse");
  if (w < 0 && l < 0 && h > 0)
    return make(Shape::disk, -l, -w, h,
                same_wl ? "vertical cylinder" : "vertical elliptical cylinder");
  if (w < 0 && l < 0 && h < 0) {
    const bool sphere = same_wl && std::abs(std::abs(h) - std::abs(w)) <= 1e-9 * std::abs(w);
    return make(Shape::disk, -l, -w, -h, sphere ? "sphere" : "ellipsoidal spheroid");
  }
  if (w < 0 && l > 0 && h < 0)
    return make(Shape::rectangle, l, -w, -h, "horizontal cylinder along C0-C180");
  if (w > 0 && l < 0 && h < 0)
    return make(Shape::rectangle, -l, w, -h, "horizontal cylinder along C90-C270");
  // Not defined by any LM-63 table: keep the sizes, choose the plainest reading, and say so.
  const std::string given =
      "(" + format_number(w) + ", " + format_number(l) + ", " + format_number(h) + ")";
  LuminousOpening o;
  if (w == 0 && l < 0 && h == 0) {
    o = make(Shape::disk, -l, -l, 0, "round (assumed)");
    warning = "luminous opening " + given + " m is not defined by LM-63; read as round, diameter " +
              format_number(-l) + " m";
  } else if (w > 0 && l == 0 && h < 0) {
    o = make(Shape::rectangle, -h, w, -h, "horizontal cylinder along C90-C270 (assumed)");
    warning = "luminous opening " + given +
              " m is not defined by LM-63; read as a horizontal "
              "cylinder along C90-C270, length " +
              format_number(w) + " m, diameter " + format_number(-h) + " m";
  } else if (w != 0 && l != 0) {
    o = make(Shape::rectangle, std::abs(l), std::abs(w), std::abs(h), "rectangle (assumed)");
    warning = "luminous opening " + given + " m is not defined by LM-63; read as a rectangle";
  } else if (w != 0 || l != 0) {
    const double d = std::max(std::abs(w), std::abs(l));
    o = make(Shape::disk, d, d, std::abs(h), "round (assumed)");
    warning = "luminous opening " + given + " m is not defined by LM-63; read as round, diameter " +
              format_number(d) + " m";
  } else {
    o = make(Shape::point, 0, 0, 0, "point (assumed)");
    warning = "luminous opening " + given + " m is not defined by LM-63; read as a point";
  }
  return o;
}

LuminousOpening eulumdat_opening(double length, double width, double height) {
  if (length <= 0 && width <= 0) return make(Shape::point, 0, 0, height, "point");
  if (width <= 0) return make(Shape::disk, length, length, height, "circle");
  if (length <= 0) return make(Shape::disk, width, width, height, "circle");
  return make(Shape::rectangle, length, width, height, "rectangle");
}

std::vector<Vec3> opening_polygon(const LuminousOpening& o, int disk_segments) {
  std::vector<Vec3> p;
  const double a = 0.5 * o.length, b = 0.5 * o.width;
  switch (o.shape) {
    case Shape::point: break;
    case Shape::rectangle:
      if (a > 0 && b > 0) p = {{a, b, 0}, {a, -b, 0}, {-a, -b, 0}, {-a, b, 0}};
      break;
    case Shape::disk: {
      if (!(a > 0 && b > 0)) break;
      const int n = std::max(3, disk_segments);
      p.reserve(static_cast<std::size_t>(n));
      for (int k = 0; k < n; ++k) {
        const double t = -2.0 * kPi * k / n;  // clockwise seen from above = ccw from below
        p.push_back({a * std::cos(t), b * std::sin(t), 0.0});
      }
      break;
    }
  }
  return p;
}

double opening_area_m2(const LuminousOpening& o) {
  switch (o.shape) {
    case Shape::rectangle: return o.length * o.width;
    case Shape::disk: return 0.25 * kPi * o.length * o.width;
    default: return 0.0;
  }
}

double projected_area_m2(const LuminousOpening& o, const Vec3& d) {
  if (o.shape == Shape::point) return 0.0;
  double a = opening_area_m2(o) * std::max(0.0, -d.z);
  if (o.height > 0.0) {
    if (o.shape == Shape::rectangle) {
      a += o.height * (o.length * std::abs(d.y) + o.width * std::abs(d.x));
    } else {
      const double ax = 0.5 * o.length * d.y, by = 0.5 * o.width * d.x;
      a += o.height * 2.0 * std::sqrt(ax * ax + by * by);
    }
  }
  return a;
}

}  // namespace luxgrid::photometry
