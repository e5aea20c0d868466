#pragma once
// Intensity from a measured (C, gamma) table: the full-sphere grid a reader produces after
// symmetry expansion (symmetry.h), looked up by direction with bilinear or Catmull-Rom bicubic
// interpolation (Wallner, "Geometry of Arbitrary Light Distributions", Sec. 4.1 [Wallner]).
//
// Conventions, stated once here:
//  * The grid is periodic in C: c_rad ascending in [0, 2 pi), the cell after the last plane wraps
//    to the first. One plane means rotational symmetry.
//  * gamma_rad is ascending inside [0, pi]. Outside [front, back] the file says nothing and the
//    intensity is zero (a downlight measured to 90 deg sends nothing upwards).
//  * The poles are single directions: where the grid reaches gamma = 0 or pi, the row there is
//    replaced by its mean over C, so the lookup is exactly continuous at the poles.
//  * Types A and B (floodlights, automotive) are stored as a C-style grid in a rotated frame;
//    `table_from_luminaire` maps a luminaire-frame direction into it (see symmetry.h).
#include <algorithm>
#include <memory>
#include <vector>

#include <glm/mat3x3.hpp>

#include "photometry/intensity_distribution.h"

namespace luxgrid::photometry {

enum class Interpolation { bilinear, bicubic };
const char* to_string(Interpolation i);

struct SphericalGrid {
  std::vector<double> c_rad;      // ascending in [0, 2 pi); size 1 = rotationally symmetric
  std::vector<double> gamma_rad;  // ascending within [0, pi], at least 2 values
  std::vector<double> cd;         // C-major: cd[i * gamma_rad.size() + j], finite, >= 0
  // Replace the rows at gamma = 0 and pi by their mean (the poles are single directions). Off
  // only for type A/B grids whose data stop short of a full turn (see symmetry.cpp).
  bool average_poles = true;
  double at(std::size_t i, std::size_t j) const { return cd[i * gamma_rad.size() + j]; }
};

class TabularDistribution final : public IntensityDistribution {
 public:
  // `table_from_luminaire` is an orthogonal matrix (possibly a reflection) taking luminaire-frame
  // directions into the grid's frame; identity for type C.
  explicit TabularDistribution(SphericalGrid grid, Interpolation mode = Interpolation::bilinear,
                               const glm::dmat3& table_from_luminaire = glm::dmat3(1.0));

  double intensity(const Vec3& direction) const override;
  // Without a frame (type C) the angles of four directions at a time (table_angles_of), each
  // looked up as intensity() looks it up; with one, one by one.
  void intensities(const double* x, const double* y, const double* z, std::size_t n,
                   double* out) const override;
  // Itself for type C; a type A/B grid's angles are not the luminaire frame's, so none.
  TableView table_view() const override { return has_frame_ ? TableView{} : TableView{this, 1.0}; }
  // Lookup by angles of the grid's own frame (radians; c any real, gamma in [0, pi]).
  double intensity_at(double c_rad, double gamma_rad) const;

  // Walking the table along one C (calc/nearfield/table_cubature.cpp): the C position is found
  // once per ray, and a lookup whose gamma cell is known (row j, fraction tg in [0, 1]) reads the
  // table directly. Same values as intensity_at(c, gamma).
  struct CPosition {
    std::size_t i = 0;  // C plane below (periodic)
    double tc = 0.0;    // fraction towards the next plane
  };
  CPosition c_position(double c_rad) const;
  // The same in two steps, for many C inside one cell of the table (the table rung's rays in
  // one psi cell, whose ends are C planes or lie between them): the C cell of `c_rad` once, then
  // the position of each c_rad in [0, 2 pi) inside that cell, the bits c_position gives.
  struct CCell {
    std::size_t i = 0;
    double c0 = 0.0, c1 = 0.0;  // the planes around it (c1 may be 2 pi past the last plane)
  };
  CCell c_cell(double c_rad) const;
  CPosition c_position_in(const CCell& cell, double c_rad) const {
    if (nc_ == 1) return CPosition{};
    return CPosition{cell.i, std::clamp((c_rad - cell.c0) / (cell.c1 - cell.c0), 0.0, 1.0)};
  }
  double intensity_at(const CPosition& c, std::size_t j, double tg) const;
  // The two C planes around a C position, for many rows at one C (the table rung's rays: its
  // closed form reads two rows per gamma interval of every ray), found once.
  struct CColumns {
    const double* v0;
    const double* v1;  // v0 when the table has one C plane (tc is 0 then)
    double tc;
    double row_value(std::size_t j) const { return v0[j] + tc * (v1[j] - v0[j]); }
  };
  CColumns c_columns(const CPosition& c) const {
    const double* v0 = grid_.cd.data() + c.i * ng_;
    if (nc_ == 1) return {v0, v0, 0.0};
    return {v0, grid_.cd.data() + (c.i + 1 < nc_ ? c.i + 1 : 0) * ng_, c.tc};
  }
  // A bilinear table's value on gamma row j at the C position (interpolated in C only): what
  // intensity_at(c, j, 0) gives, and intensity_at(c, j - 1, 1) up to rounding.
  double row_value(const CPosition& c, std::size_t j) const { return c_columns(c).row_value(j); }
  // The gamma cell of an angle: false outside the table's gamma range (intensity zero there).
  bool gamma_cell(double gamma_rad, std::size_t& j, double& tg) const;

  Interpolation interpolation() const { return mode_; }
  std::shared_ptr<const TabularDistribution> with_interpolation(Interpolation mode) const;
  std::shared_ptr<const TabularDistribution> scaled(double factor) const;

  const SphericalGrid& grid() const { return grid_; }
  bool has_frame() const { return has_frame_; }
  const glm::dmat3& table_from_luminaire() const { return frame_; }
  // Direction of grid angles (c, gamma) in the luminaire frame.
  Vec3 luminaire_direction(double c_rad, double gamma_rad) const;

 private:
  struct Cell {
    std::size_t i;  // C plane below (periodic)
    double tc;      // fraction in C
    std::size_t j;  // gamma row below
    double tg;      // fraction in gamma
  };
  bool locate(double c, double g, Cell& cell) const;
  double bilinear(const Cell& cell) const;
  double bicubic(const Cell& cell) const;
  double c_of(long k) const;  // periodic C position of plane index k (any integer)

  SphericalGrid grid_;
  Interpolation mode_;
  glm::dmat3 frame_;
  bool has_frame_;
  std::size_t nc_, ng_;
  // Regular grids (most files) find their cell by one multiplication instead of a search.
  bool c_uniform_ = false, g_uniform_ = false;
  double inv_dc_ = 0.0, inv_dg_ = 0.0;
  double g_front_, g_back_;
};

}  // namespace luxgrid::photometry
