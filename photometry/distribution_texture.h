#pragma once
// A "light distribution texture" ([Wallner, Sec. 4]): the distribution resampled once on
// a regular grid, so that a lookup is a few multiplications and no search.
//
// Wallner indexes his texture by (C, gamma), which costs two inverse trigonometric calls per
// lookup. This texture is indexed by two *diamond angles* instead, computed from the direction
// with additions, one square root and one division (no trigonometry):
//   u = diamond angle of (x, y), in [0, 4): 0 at C0, 1 at C90, 2 at C180, 3 at C270
//   v = diamond angle of (h, -z) with h = |(x, y)|, in [0, 2]: 0 at nadir, 1 at the horizon
// Both are monotonic in the true angles, u in C alone and v in gamma alone, so the texture's
// rows are cones of constant gamma and its columns planes of constant C, as the table's are (an
// octahedral v = (|x| + |y|) / (|x| + |y| + |z|) saves the square root but crosses the table's
// gamma rows diagonally: 2 to 15 times the deviation on the test corpus). The grid is regular in
// (u, v), so its angular spacing varies by at most a factor of 2 (finest at the axes, coarsest
// at 45 deg). Texels are sampled from the source distribution at their exact directions; a
// direction need not be a unit vector (u and v are ratios of its components).
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "photometry/intensity_distribution.h"
#include "photometry/tabular_distribution.h"

namespace luxgrid::photometry {

class DistributionTexture final : public IntensityDistribution {
 public:
  // `c_cells` texels around (periodic), `gamma_cells` from nadir to zenith (gamma_cells + 1 rows).
  DistributionTexture(const IntensityDistribution& source, int c_cells = 720, int gamma_cells = 360,
                      Interpolation mode = Interpolation::bilinear);
  // From texels already sampled (texel(i, j) = source at texel_direction(i, j, ...), row-major
  // by gamma row, c_cells x (gamma_cells + 1)): a caller samples them in parallel
  // (calc/intensity_lookup.cpp).
  DistributionTexture(int c_cells, int gamma_cells, std::vector<float> texels,
                      Interpolation mode = Interpolation::bilinear);

  double intensity(const Vec3& direction) const override;
  // The bilinear lookup without the virtual call, for the hot loops that know the texture they
  // hold (calc/direct.cpp); the same value as intensity() on a bilinear texture.
  inline double bilinear(const Vec3& direction) const;
  // bilinear() of n directions given as three arrays (x[k], y[k], z[k]), into out[k]: the same
  // values to the last bit. The coordinates of all n are worked out first, in a loop without
  // branches that the compiler turns into vector instructions, then the texels are read: the
  // far-field loop of calc/direct.cpp looks up a run of points at once.
  void bilinear_batch(const double* x, const double* y, const double* z, int n, double* out) const;
  Interpolation interpolation() const { return mode_; }
  int c_cells() const { return nu_; }
  int gamma_cells() const { return nv_; }

  // The texture coordinates (diamond angles) of a direction and back.
  static inline void diamond_angles(const Vec3& d, double& u, double& v);
  static Vec3 direction_of_diamond(double u, double v);
  // The direction texel (i, j) samples: column i of c_cells, row j of gamma_cells + 1 (rows 0
  // and gamma_cells are the poles).
  static Vec3 texel_direction(int i, int j, int c_cells, int gamma_cells);

 private:
  // The texel cell a direction falls in: columns i and i1 (wrapping around), row j, and the
  // fractions su, sv across the cell.
  struct Cell {
    int i, j, i1;
    double su, sv;
  };
  inline Cell cell_of(const Vec3& direction) const;
  double texel(int i, int j) const {
    return data_[static_cast<std::size_t>(j) * static_cast<std::size_t>(nu_) +
                 static_cast<std::size_t>(i)];
  }
  int nu_, nv_;
  Interpolation mode_;
  std::vector<float> data_;  // row-major by v; float halves the memory, error ~1e-7 relative
};

void DistributionTexture::diamond_angles(const Vec3& d, double& u, double& v) {
  // t = y / (|x| + |y|) and q = h / (h + |z|) share one division (the hot path's cost).
  const double sxy = std::abs(d.x) + std::abs(d.y);
  const double h = std::sqrt(d.x * d.x + d.y * d.y);
  const double a = -d.z;
  const double s = h + std::abs(a);
  if (sxy > 0.0) {
    const double inv = 1.0 / (sxy * s);
    const double t = d.y * s * inv;  // in [-1, 1]
    // Quadrants 1 and 4, then 2 and 3. u = 4 (t = -0) is column 0 again: the lookup clamps it
    // to the last column at fraction 1, which reads column 0.
    u = d.x >= 0.0 ? (t >= 0.0 ? t : 4.0 + t) : 2.0 - t;
    const double q = h * sxy * inv;  // in (0, 1]
    v = a >= 0.0 ? q : 2.0 - q;
  } else {
    u = 0.0;  // a pole: every column holds the same value there
    v = a >= 0.0 ? 0.0 : 2.0;
  }
}

inline DistributionTexture::Cell DistributionTexture::cell_of(const Vec3& d) const {
  double u, v;
  diamond_angles(d, u, v);
  // max(0, NaN) is 0: a degenerate direction (a length near the underflow) reads a texel
  // instead of an index out of range.
  const double fu = std::min(std::max(0.0, u * (nu_ / 4.0)), static_cast<double>(nu_));
  const double fv = std::min(std::max(0.0, v * (nv_ / 2.0)), static_cast<double>(nv_));
  Cell c;
  c.i = static_cast<int>(fu), c.j = static_cast<int>(fv);
  if (c.i >= nu_) c.i = nu_ - 1;
  if (c.j >= nv_) c.j = nv_ - 1;
  c.su = fu - c.i, c.sv = fv - c.j;
  c.i1 = c.i + 1 == nu_ ? 0 : c.i + 1;
  return c;
}

inline double DistributionTexture::bilinear(const Vec3& d) const {
  const auto [i, j, i1, su, sv] = cell_of(d);
  const double a = texel(i, j) + su * (texel(i1, j) - texel(i, j));
  const double b = texel(i, j + 1) + su * (texel(i1, j + 1) - texel(i, j + 1));
  return a + sv * (b - a);
}

}  // namespace luxgrid::photometry
