#include "report/csv.h"

#include <cstdio>

namespace luxgrid::report {

namespace {
// An observers surface: a row per view with the eye, the line of sight, UGR (empty when no
// luminaire is in the view), the background luminance and the illuminance at the eye.
std::string observers_csv(const calc::SurfaceResult& r) {
  std::string out = "observer,x,y,z,dx,dy,dz,UGR,Lb_cd_m2,E_lx,E_indirect_lx\n";
  char line[512];
  size_t k = 0;
  for (size_t o = 0; o < r.observers.size(); ++o) {
    for (const auto& v : r.observers[o].views) {
      char ugr[32] = "";
      if (v.UGR) std::snprintf(ugr, sizeof ugr, "%.6g", *v.UGR);
      const auto& p = r.observers[o].at;
      std::snprintf(line, sizeof line, "%zu,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%s,%.6g,%.6g,%.6g\n", o,
                    p.x, p.y, p.z, v.direction.x, v.direction.y, v.direction.z, ugr, v.Lb_cd_m2,
                    k < r.E.size() ? r.E[k] : 0.0, v.E_indirect_lx);
      out += line;
      ++k;
    }
  }
  return out;
}
}  // namespace

std::string surface_csv(const calc::SurfaceResult& r) {
  if (r.grid.kind == geometry::SurfaceGrid::Kind::observers) return observers_csv(r);
  // The last column says what the E columns measure (results.json's "quantity"), so a CSV read on
  // its own cannot pass a cylindrical value off as a planar one. nx, ny, nz are the receiver
  // normal: for a semi-cylindrical surface the direction the half cylinder faces. A point left
  // out of the calculation (outside an L-shaped workplane, inside an obstacle) says active =
  // false and leaves its E cells empty, so a spreadsheet's MIN and AVERAGE over a column skip
  // it, as the statistics do.
  std::string out = std::string(kSurfaceCsvHeader) + "\n";
  const auto& g = r.grid;
  const char* quantity = geometry::to_string(g.quantity);
  char line[512];
  for (size_t k = 0; k < g.points.size(); ++k) {
    const int nu = g.nu > 0 ? g.nu : 1;
    const auto& p = g.points[k];
    const auto& n = g.normals[k];
    const bool active = g.active.empty() || g.active[k];
    std::snprintf(line, sizeof line, "%d,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,",
                  static_cast<int>(k % nu), static_cast<int>(k / nu), p.x, p.y, p.z, n.x, n.y, n.z);
    out += line;
    if (active) {
      std::snprintf(line, sizeof line, "true,%.6g,%.6g,%.6g,%s\n", r.E[k], r.E_direct[k],
                    r.E_indirect[k], quantity);
    } else {
      std::snprintf(line, sizeof line, "false,,,,%s\n", quantity);
    }
    out += line;
  }
  return out;
}

}  // namespace luxgrid::report
