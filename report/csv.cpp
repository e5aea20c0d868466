#include "report/csv.h"

#include <cstdio>

namespace luxgrid::report {

std::string surface_csv(const calc::SurfaceResult& r) {
  // The last column says what the E columns measure (results.json's "quantity"), so a CSV read on
  // its own cannot pass a cylindrical value off as a planar one. nx, ny, nz are the receiver
  // normal: for a semi-cylindrical surface the direction the half cylinder faces.
  std::string out = "i,j,x,y,z,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,quantity\n";
  const auto& g = r.grid;
  const char* quantity = geometry::to_string(g.quantity);
  char line[512];
  for (size_t k = 0; k < g.points.size(); ++k) {
    const int nu = g.nu > 0 ? g.nu : 1;
    const auto& p = g.points[k];
    const auto& n = g.normals[k];
    std::snprintf(line, sizeof line, "%d,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%s\n",
                  static_cast<int>(k % nu), static_cast<int>(k / nu), p.x, p.y, p.z, n.x, n.y, n.z,
                  r.E[k], r.E_direct[k], r.E_indirect[k], quantity);
    out += line;
  }
  return out;
}

}  // namespace luxgrid::report
