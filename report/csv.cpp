#include "report/csv.h"

#include <cstdio>

namespace luxgrid::report {

std::string surface_csv(const calc::SurfaceResult& r) {
  std::string out = "i,j,x,y,z,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx\n";
  const auto& g = r.grid;
  char line[512];
  for (size_t k = 0; k < g.points.size(); ++k) {
    const int nu = g.nu > 0 ? g.nu : 1;
    const auto& p = g.points[k];
    const auto& n = g.normals[k];
    std::snprintf(line, sizeof line, "%d,%d,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n",
                  static_cast<int>(k % nu), static_cast<int>(k / nu), p.x, p.y, p.z, n.x, n.y, n.z,
                  r.E[k], r.E_direct[k], r.E_indirect[k]);
    out += line;
  }
  return out;
}

}  // namespace luxgrid::report
