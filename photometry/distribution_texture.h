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
#include "util/simd.h"

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
  const std::vector<float>& texels() const { return data_; }
  Interpolation interpolation() const { return mode_; }
  int c_cells() const { return nu_; }
  int gamma_cells() const { return nv_; }

  // The texture coordinates (diamond angles) of a direction and back.
  static inline void diamond_angles(const Vec3& d, double& u, double& v);
  static Vec3 direction_of_diamond(double u, double v);
  // The direction texel (i, j) samples: column i of c_cells, row j of gamma_cells + 1 (rows 0
  // and gamma_cells are the poles).
  static Vec3 texel_direction(int i, int j, int c_cells, int gamma_cells);

  // The texel cell a direction falls in: columns i and i1 (wrapping around), row j, and the
  // fractions su, sv across the cell.
  struct Cell {
    int i, j, i1;
    double su, sv;
  };
  // The cell of the texel position (fu, fv) (texel_position), and the bilinear value there on the
  // texels (row-major by gamma row, nu per row): shared by bilinear() and bilinear_batch.
  static inline Cell cell_at(double fu, double fv, int nu, int nv);
  static inline double bilinear_in(const float* texels, int nu, const Cell& cell);

 private:
  inline Cell cell_of(const Vec3& direction) const;
  double texel(int i, int j) const {
    return data_[static_cast<std::size_t>(j) * static_cast<std::size_t>(nu_) +
                 static_cast<std::size_t>(i)];
  }
  int nu_, nv_;
  Interpolation mode_;
  std::vector<float> data_;  // row-major by v; float halves the memory, error ~1e-7 relative
};

// The diamond angles (u, v) of the direction (x, y, z) (any length), over one direction or lanes
// (T = double or simd::D4), every branch computed and selected: at a pole (x = y = 0) the
// quotients are NaN and not selected. t = y / (|x| + |y|) and q = h / (h + |z|) share one
// division (the hot path's cost).
template <class T>
LUXGRID_LANE void diamond_uv(const T& x, const T& y, const T& z, T& u, T& v) {
  const T sxy = simd::abs(x) + simd::abs(y);
  const T h = simd::sqrt(x * x + y * y);
  const T a = -z;
  const T s = h + simd::abs(a);
  const T inv = 1.0 / (sxy * s);
  const T t = y * s * inv;    // in [-1, 1]
  const T q = h * sxy * inv;  // in (0, 1]
  const T zero = simd::splat<T>(0.0), two = simd::splat<T>(2.0);
  const simd::Mask<T> pole = simd::logical_not(sxy > 0.0), up = a >= 0.0;
  // Quadrants 1 and 4, then 2 and 3. u = 4 (t = -0) is column 0 again: the lookup clamps it to
  // the last column at fraction 1, which reads column 0. A pole: every column holds the same
  // value there.
  u = simd::select(pole, zero, simd::select(x >= 0.0, simd::select(t >= 0.0, t, 4.0 + t), 2.0 - t));
  v = simd::select(pole, simd::select(up, zero, two), simd::select(up, q, 2.0 - q));
}

// The texel position (fu, fv) in [0, nu] x [0, nv] of the direction (x, y, z) on a texture of
// nu columns and nv rows: the diamond angles scaled, std::max(0, .) and std::min(., nu) spelled
// out. max(0, NaN) is 0: a degenerate direction (a length near the underflow) reads a texel
// instead of an index out of range.
template <class T>
LUXGRID_LANE void texel_position(const T& x, const T& y, const T& z, int nu, int nv, T& fu, T& fv) {
  T u, v;
  diamond_uv(x, y, z, u, v);
  const T fu0 = u * (nu / 4.0), fv0 = v * (nv / 2.0);
  const T zero = simd::splat<T>(0.0);
  const T fu1 = simd::select(0.0 < fu0, fu0, zero), fv1 = simd::select(0.0 < fv0, fv0, zero);
  const T u_max = simd::splat<T>(static_cast<double>(nu)), v_max = simd::splat<T>(nv);
  fu = simd::select(u_max < fu1, u_max, fu1);
  fv = simd::select(v_max < fv1, v_max, fv1);
}

void DistributionTexture::diamond_angles(const Vec3& d, double& u, double& v) {
  diamond_uv(d.x, d.y, d.z, u, v);
}

DistributionTexture::Cell DistributionTexture::cell_at(double fu, double fv, int nu, int nv) {
  Cell c;
  c.i = std::min(static_cast<int>(fu), nu - 1), c.j = std::min(static_cast<int>(fv), nv - 1);
  c.su = fu - c.i, c.sv = fv - c.j;
  c.i1 = c.i + 1 == nu ? 0 : c.i + 1;
  return c;
}

inline DistributionTexture::Cell DistributionTexture::cell_of(const Vec3& d) const {
  double fu, fv;
  texel_position(d.x, d.y, d.z, nu_, nv_, fu, fv);
  return cell_at(fu, fv, nu_, nv_);
}

double DistributionTexture::bilinear_in(const float* texels, int nu, const Cell& c) {
  const auto texel = [&](int i, int j) {
    return static_cast<double>(texels[static_cast<std::size_t>(j) * static_cast<std::size_t>(nu) +
                                      static_cast<std::size_t>(i)]);
  };
  const double a = texel(c.i, c.j) + c.su * (texel(c.i1, c.j) - texel(c.i, c.j));
  const double b = texel(c.i, c.j + 1) + c.su * (texel(c.i1, c.j + 1) - texel(c.i, c.j + 1));
  return a + c.sv * (b - a);
}

inline double DistributionTexture::bilinear(const Vec3& d) const {
  return bilinear_in(data_.data(), nu_, cell_of(d));
}

// DistributionTexture::bilinear_batch on its texels (texels(), c_cells(), gamma_cells()): one
// version per target (util/simd.h's LUXGRID_MULTIVERSION), each callable by name.
LUXGRID_MULTIVERSION_DECLARE(void, bilinear_batch_texels,
                             (const float* texels, int nu, int nv, const double* x, const double* y,
                              const double* z, int n, double* out))

}  // namespace luxgrid::photometry
