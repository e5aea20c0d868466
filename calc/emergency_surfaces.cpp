#include "calc/emergency_surfaces.h"

#include <algorithm>
#include <cmath>

namespace luxgrid::calc {

namespace {

// Steps of at most `spacing_m` over `length_m`: at least one.
double steps(double length_m, double spacing_m) {
  return std::max(1.0, std::ceil(length_m / spacing_m));
}

// Steps on each side of the centre across the central band: at least one, so the band's edges
// are always points.
double band_steps_per_side(double width_m, double spacing_m) {
  return steps(0.5 * kCentralBandFraction * width_m, spacing_m);
}

}  // namespace

const char* to_string(EmergencyRole role) {
  switch (role) {
    case EmergencyRole::route_centre_line: return "escape route centre line";
    case EmergencyRole::route_band: return "escape route central band";
    case EmergencyRole::open_area: return "open area";
  }
  return "?";
}

double path_length(const geometry::Polygon2& path) {
  double length = 0.0;
  for (size_t k = 0; k + 1 < path.size(); ++k) length += glm::length(path[k + 1] - path[k]);
  return length;
}

double escape_route_point_count(const geometry::Polygon2& path, double width_m, double spacing_m) {
  double stations = 1.0;
  for (size_t k = 0; k + 1 < path.size(); ++k)
    stations += steps(glm::length(path[k + 1] - path[k]), spacing_m);
  return stations * (1.0 + 2.0 * band_steps_per_side(width_m, spacing_m) + 1.0);
}

EscapeRoutePoints escape_route_points(const geometry::Polygon2& path, double width_m,
                                      double spacing_m) {
  EscapeRoutePoints out;
  const double half_band = 0.5 * kCentralBandFraction * width_m;
  const int per_side = static_cast<int>(band_steps_per_side(width_m, spacing_m));
  auto add_station = [&](const Vec2& at, const Vec2& across) {
    out.centre_line.push_back(at);
    for (int j = -per_side; j <= per_side; ++j) {
      out.band.push_back(at + across * (half_band * j / per_side));
    }
  };
  for (size_t k = 0; k + 1 < path.size(); ++k) {
    const Vec2 a = path[k], b = path[k + 1];
    const Vec2 along = b - a;
    const double length = glm::length(along);
    const Vec2 across = Vec2(-along.y, along.x) / length;  // the segment's left-hand normal
    const int n = static_cast<int>(steps(length, spacing_m));
    // The first segment gives its start; every later one starts at the previous one's end.
    for (int j = k == 0 ? 0 : 1; j <= n; ++j) {
      // The last station is the corner itself, not a + n * (along / n) rounded.
      add_station(j == n ? b : a + along * (static_cast<double>(j) / n), across);
    }
  }
  return out;
}

geometry::SurfaceGrid floor_points_grid(const std::string& name, const std::vector<Vec2>& points,
                                        double z) {
  geometry::SurfaceGrid g;
  g.name = name;
  g.kind = geometry::SurfaceGrid::Kind::points;
  g.quantity = geometry::Quantity::horizontal;
  for (const Vec2& p : points) {
    g.points.emplace_back(p.x, p.y, z);
    g.normals.emplace_back(0.0, 0.0, 1.0);
  }
  g.nu = static_cast<int>(g.points.size());
  g.nv = 1;
  g.active.assign(g.points.size(), true);
  return g;
}

}  // namespace luxgrid::calc
