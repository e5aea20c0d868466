#include "geometry/surface_grid.h"

#include <algorithm>
#include <cmath>

namespace luxgrid::geometry {

const char* to_string(Quantity q) {
  switch (q) {
    case Quantity::planar: return "planar";
    case Quantity::horizontal: return "horizontal";
    case Quantity::vertical: return "vertical";
    case Quantity::cylindrical: return "cylindrical";
    case Quantity::semi_cylindrical: return "semi-cylindrical";
  }
  return "planar";
}

const char* to_string(SurfaceGrid::Kind kind) {
  switch (kind) {
    case SurfaceGrid::Kind::grid: return "grid";
    case SurfaceGrid::Kind::points: return "points";
    case SurfaceGrid::Kind::observers: return "observers";
  }
  return "grid";
}

double auto_spacing(double longer_side) {
  // EN 12464-1:2021 (and EN 12464-1:2011 Annex B / ISO 30061-style grids):
  // p = 0.2 * 5^log10(d) metres, d the longer side of the area; p never exceeds 10 m.
  constexpr double kMaxSpacing = 10.0;  // m, the standard's cap
  if (longer_side <= 0.0) return 0.0;
  return std::min(kMaxSpacing, 0.2 * std::pow(5.0, std::log10(longer_side)));
}

SurfaceGrid make_plane_grid(const std::string& name, const Vec3& origin, const Vec3& u,
                            const Vec3& v, double size_u, double size_v, double spacing) {
  SurfaceGrid g;
  g.name = name;
  g.kind = SurfaceGrid::Kind::grid;
  g.origin = origin;
  g.u_dir = glm::normalize(u);
  g.v_dir = glm::normalize(v);
  g.size_u = size_u;
  g.size_v = size_v;
  // At least one cell per side; cells no larger than `spacing` (the usual rule: the number of
  // points is rounded up, so the actual spacing is never coarser than asked).
  // pieces_of_at_most: 4 m / 0.25 m gives 16 cells, not 17
  g.nu = pieces_of_at_most(size_u / spacing);
  g.nv = pieces_of_at_most(size_v / spacing);
  g.spacing_u = size_u / g.nu;
  g.spacing_v = size_v / g.nv;
  const Vec3 normal = glm::normalize(glm::cross(g.u_dir, g.v_dir));
  g.points.reserve(static_cast<size_t>(g.nu) * g.nv);
  g.normals.reserve(g.points.capacity());
  for (int j = 0; j < g.nv; ++j) {
    for (int i = 0; i < g.nu; ++i) {
      g.points.push_back(origin + g.u_dir * ((i + 0.5) * g.spacing_u) +
                         g.v_dir * ((j + 0.5) * g.spacing_v));
      g.normals.push_back(normal);
    }
  }
  g.active.assign(g.points.size(), true);
  return g;
}

}  // namespace luxgrid::geometry
