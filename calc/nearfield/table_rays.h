#pragma once
// The table rung's second and third steps (calc/nearfield/table_cubature.cpp): the rays of its
// psi cells (each cell's Gauss-Legendre nodes in psi), and where each ray enters and leaves the
// opening, with sin, cos, tan and the table angle of gamma' at both ends. The ends of rays through
// known edges are one formula over one ray or four (ends_through_edges), the four-lane version
// multiversioned (util/simd.h).
#include <cstddef>
#include <vector>

#include "calc/nearfield/table_polygon.h"
#include "calc/nearfield/table_psi_cells.h"
#include "photometry/tabular_distribution.h"
#include "util/simd.h"
#include "util/table_angle.h"

namespace luxgrid::nearfield {

// A ray of the rung's psi cells: its angle and direction, its share 0.5 x cell width x Gauss
// weight, and what its cell's rays share: the table's C cell, the cell's index, and with F
// outside the edges it enters and leaves through (near_edge < 0: every edge is tried).
struct RayJob {
  double psi, c, s, scale;
  photometry::TabularDistribution::CCell c_cell;
  std::size_t cell;
  int near_edge, far_edge;
};

// Where a ray enters and leaves the opening: sin, cos and tan of gamma' and its table angle at
// both ends (ok false: the ray misses the opening, by rounding at the rim of the range).
struct RayEnds {
  bool ok;
  double sin_near, cos_near, sin_far, cos_far, tan_near, tan_far, g_near, g_far;
};

// The rays of the cells psi.breaks, in order, into jobs[0..count) (grown when too small): each
// cell's Gauss pair or wide rule (finish_breaks), with the table's C cell of the cell's middle
// and, with F outside, the edges its rays cross. Returns count.
std::size_t cell_rays(const Polygon2& poly, const PsiCells& psi,
                      const photometry::TabularDistribution& table, std::vector<RayJob>& jobs);

// The ends of rays that enter and leave through known edges, over one ray or four (T = double or
// simd::D4): the ray's direction (c, s), per edge its vector e and cross term (Polygon2). On an
// edge rho = cross / det (edge_det), so tan(gamma') = rho / |sigma| = x / det with
// x = cross / |sigma|, and (sin, cos) = (|x|, |det|) / sqrt(x^2 + det^2): after the determinant
// one square root and one division, where going through tan takes a division, a square root and
// another division one after the other. ok: the ray reaches the opening (rho_max > rho_min >= 0).
template <class T>
struct EdgeEnds {
  simd::Mask<T> ok;
  T sin_near, cos_near, sin_far, cos_far, tan_near, tan_far, g_near, g_far;
};
template <class T>
LUXGRID_LANE EdgeEnds<T> ends_through_edges(const T& c, const T& s, const T& near_x,
                                            const T& near_y, const T& near_cross, const T& far_x,
                                            const T& far_y, const T& far_cross, double inv_sigma) {
  EdgeEnds<T> out;
  const T det_near = -c * near_y + s * near_x, det_far = -c * far_y + s * far_x;
  const T rho_min = near_cross / det_near, rho_max = far_cross / det_far;
  out.ok = simd::logical_and(rho_max > rho_min, rho_min >= 0.0);
  const T x_near = near_cross * inv_sigma, x_far = far_cross * inv_sigma;
  const T inv_near = 1.0 / simd::sqrt(x_near * x_near + det_near * det_near),
          inv_far = 1.0 / simd::sqrt(x_far * x_far + det_far * det_far);
  out.cos_near = simd::abs(det_near) * inv_near, out.sin_near = simd::abs(x_near) * inv_near;
  out.cos_far = simd::abs(det_far) * inv_far, out.sin_far = simd::abs(x_far) * inv_far;
  out.tan_near = rho_min * inv_sigma, out.tan_far = rho_max * inv_sigma;
  out.g_near = quadrant_angle(out.sin_near, out.cos_near);
  out.g_far = quadrant_angle(out.sin_far, out.cos_far);
  return out;
}

// ends_through_edges for the four rays jobs[0..4), all with near_edge >= 0, into ends[0..4):
// one version per target (util/simd.h's LUXGRID_MULTIVERSION).
LUXGRID_MULTIVERSION_DECLARE(void, ends_by_edges4,
                             (const Polygon2& poly, const RayJob* jobs, double inv_sigma,
                              RayEnds* ends))

// The ends of rays jobs[0..count) into ends[0..count), for the opening poly (F inside it or not)
// at the receiver's distance 1 / inv_sigma from its plane: through the known edges by
// ends_through_edges, four at once where four consecutive rays have them (the same bits as one
// by one), else every edge tried (ray_interval).
void ray_ends(const Polygon2& poly, bool inside, double inv_sigma, const RayJob* jobs,
              std::size_t count, RayEnds* ends);

}  // namespace luxgrid::nearfield
