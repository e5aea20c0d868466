#pragma once
// EN 1838 calculation surfaces [EN1838]: escape routes (the centre line and the central band on
// the floor) and open areas (anti-panic: the floor without a 0.5 m border). The project loader
// reads their keys (docs/project-format.md); this file holds their geometry and the EN 1838
// figures, so that the loader, the checks (report/requirement_checks_en1838) and the tests share
// them.
#include <string>
#include <vector>

#include "geometry/polygon.h"
#include "geometry/surface_grid.h"

namespace luxgrid::calc {

// EN 1838:2013 clause 4.2: the rules for an escape route hold for routes up to 2 m wide (a
// wider route is treated as several 2 m strips, or as an open area); the central band is at
// least half the route's width.
inline constexpr double kMaxEscapeRouteWidth_m = 2.0;
inline constexpr double kCentralBandFraction = 0.5;
// EN 1838:2013 clause 4.3: an open area's core excludes a border of 0.5 m along its perimeter.
inline constexpr double kOpenAreaBorder_m = 0.5;

// The limits [EN1838] (clause 4.2, escape routes; clause 4.3, open areas).
inline constexpr double kRouteCentreLineEmin_lx = 1.0;
inline constexpr double kRouteBandEmin_lx = 0.5;  // 50 % of the centre line's 1 lx
inline constexpr double kOpenAreaEmin_lx = 0.5;
inline constexpr double kMaxDiversity = 40.0;  // Emax / Emin, centre line and open area

// What an EN 1838 grid is, for the checks.
enum class EmergencyRole { route_centre_line, route_band, open_area };
const char* to_string(EmergencyRole role);  // "escape route centre line", ...

struct EmergencySurface {
  std::string grid;   // the grid's name ("exit centre line", "exit band", "hall")
  std::string entry;  // the project surface entry it came from ("exit", "hall")
  EmergencyRole role = EmergencyRole::open_area;
};

// The points of an escape route along the polyline `path` (at least two corners, consecutive
// corners distinct), `width_m` wide, `spacing_m` apart at most. Each segment is divided into
// ceil(length / spacing) equal steps and every step's end is a station, so the route's corners and
// both ends are stations (the first segment also gives its start). The centre line is the
// stations; the band is, at every station, 2 ceil((band / 2) / spacing) + 1 points evenly across
// the central band of width kCentralBandFraction x width_m (from -band / 2 to +band / 2,
// the centre included), perpendicular to the station's own segment (a corner belongs to the
// segment ending there), so every band point lies within band / 2 of the centre line.
struct EscapeRoutePoints {
  std::vector<Vec2> centre_line;
  std::vector<Vec2> band;
};
EscapeRoutePoints escape_route_points(const geometry::Polygon2& path, double width_m,
                                      double spacing_m);

// The number of centre-line and band points escape_route_points gives, computed in double before
// anything is allocated (for the loader's point budget).
double escape_route_point_count(const geometry::Polygon2& path, double width_m, double spacing_m);

// The polyline's length, m.
double path_length(const geometry::Polygon2& path);

// A points grid on the floor at height z: horizontal illuminance (normal +z) at each point.
geometry::SurfaceGrid floor_points_grid(const std::string& name, const std::vector<Vec2>& points,
                                        double z);

}  // namespace luxgrid::calc
