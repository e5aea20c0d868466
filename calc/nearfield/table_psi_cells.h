#pragma once
// The table rung's first step, its cells in psi (calc/nearfield/table_cubature.cpp): the angular
// range of the opening seen from the receiver's foot F, cut wherever the integrand along the rays
// has a kink (a vertex direction, a table C line, a gamma circle crossing the outline), and the
// Gauss-Legendre rule of each cell.
#include <array>
#include <cmath>
#include <vector>

#include "calc/nearfield/table_cells.h"
#include "calc/nearfield/table_polygon.h"
#include "util/robust_math.h"

namespace luxgrid::nearfield {

// Largest angular width of a psi cell (rad, 7.5 deg) when the table has no C line inside it
// (rotationally symmetric files have none): the outline rho(psi) and the weight must still be
// resolved. The gamma side's limits are in table_cells.h.
inline constexpr double kMaxPsiCell = 7.5 * kPi / 180.0;
// Cells narrower than this (rad) are dropped: two breaks that coincide up to rounding.
inline constexpr double kMinCell = 1e-12;

// x - 2 pi floor((x - lo) / 2 pi): the copy of angle x in [lo, lo + 2 pi), the same bits, without
// floor's call for the angles the rung meets (at most a turn away).
inline double first_copy_at_or_above(double x, double lo) {
  const double turns = (x - lo) / kTwoPi;
  if (turns >= 0.0 && turns < 1.0) return x - kTwoPi * 0.0;
  if (turns >= 1.0 && turns < 2.0) return x - kTwoPi * 1.0;
  if (turns >= -1.0 && turns < 0.0) return x - kTwoPi * -1.0;
  return x - kTwoPi * std::floor(turns);
}

// A psi break: its angle and its direction (cos, sin), the direction taken from the geometry
// that made the break (a vertex, a circle crossing, a C plane), so that a cell's middle direction
// is the normalised sum of its ends': no sine and cosine per cell.
struct Break {
  double psi, c, s;
  int points = 2;  // the Gauss-Legendre rule of the cell that starts here (finish_breaks)
};

// What psi_cells (below) makes: the breaks, and with F outside each edge's angular span.
struct PsiCells {
  std::vector<Break> breaks;  // sorted
  bool outside = false;
  double psi_mid = 0.0;  // spans are relative to it
  std::array<double, kMaxPolygonVertices> span_lo{}, span_hi{};
  std::array<bool, kMaxPolygonVertices> facing{};

  // The edges a ray at psi (inside the range, F outside) enters and leaves through: false where
  // the spans do not tell (F on an edge's line), and the caller tests every edge.
  bool edges_of(double psi, int n, int& near, int& far) const {
    const double rel = psi - psi_mid;
    near = far = -1;
    for (int i = 0; i < n; ++i)
      if (span_lo[i] < rel && rel < span_hi[i]) (facing[i] ? near : far) = i;
    return near >= 0 && far >= 0;
  }
};

// The psi cells of one receiver: the angular range of the polygon seen from F (all around when
// F is inside), cut at the polygon's vertex directions (rho(psi) has a corner there), at the
// table's C lines (C = psi + pi), and where a gamma line (a circle of radius |sigma| tan gamma'
// around F) crosses the outline: there a ray's first or last gamma cell changes, a kink in psi.
// With F outside, each edge's angular span and whether it faces F: a ray in a cell enters through
// the facing edge whose span holds the cell and leaves through the other (edges_of). `scratch`
// is working space (the caller's, kept between calls). False when the range is empty.
bool psi_cells(const Polygon2& poly, bool inside, bool front, double abs_sigma, double reach,
               const TableGammaCells& cells, const std::vector<double>& c_lines, PsiCells& out,
               std::vector<Break>& scratch);

}  // namespace luxgrid::nearfield
