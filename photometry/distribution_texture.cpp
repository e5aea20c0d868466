#include "photometry/distribution_texture.h"

#include <algorithm>
#include <cmath>

#include "util/error.h"

namespace luxgrid::photometry {

namespace {
// Catmull-Rom weights on a regular grid (interpolating; the uniform case of the Hermite weights
// in tabular_distribution.cpp).
inline void catmull_rom(double s, double w[4]) {
  const double s2 = s * s, s3 = s2 * s;
  w[0] = 0.5 * (-s3 + 2 * s2 - s);
  w[1] = 0.5 * (3 * s3 - 5 * s2 + 2);
  w[2] = 0.5 * (-3 * s3 + 4 * s2 + s);
  w[3] = 0.5 * (s3 - s2);
}
}  // namespace

Vec3 DistributionTexture::direction_of_diamond(double u, double v) {
  // Inverse of diamond_angles: in each quadrant the diamond angle t maps to the point (1-t, t).
  double x, y;
  const double q = std::floor(u);
  const double t = u - q;
  switch (static_cast<int>(q) & 3) {
    case 0: x = 1 - t, y = t; break;
    case 1: x = -t, y = 1 - t; break;
    case 2: x = -(1 - t), y = -t; break;
    default: x = t, y = -(1 - t); break;
  }
  const double r = std::hypot(x, y);
  double h, a;  // horizontal and downward components before normalising
  if (v <= 1.0)
    h = v, a = 1.0 - v;
  else
    h = 2.0 - v, a = -(v - 1.0);
  const double len = std::hypot(h, a);
  h /= len, a /= len;
  return {h * x / r, h * y / r, -a};
}

Vec3 DistributionTexture::texel_direction(int i, int j, int c_cells, int gamma_cells) {
  if (j == 0 || j == gamma_cells) return {0.0, 0.0, j == 0 ? -1.0 : 1.0};  // a pole: one direction
  return direction_of_diamond(4.0 * i / c_cells, 2.0 * j / gamma_cells);
}

namespace {
void check_resolution(int nu, int nv) {
  if (nu < 4 || nv < 2 || static_cast<long>(nu) * (nv + 1) > 50'000'000L)
    throw CalculationError("DistributionTexture: resolution out of range");
}
}  // namespace

DistributionTexture::DistributionTexture(const IntensityDistribution& source, int c_cells,
                                         int gamma_cells, Interpolation mode)
    : nu_(c_cells), nv_(gamma_cells), mode_(mode) {
  check_resolution(nu_, nv_);
  data_.resize(static_cast<std::size_t>(nu_) * static_cast<std::size_t>(nv_ + 1));
  for (int j = 0; j <= nv_; ++j)
    for (int i = 0; i < nu_; ++i)
      data_[static_cast<std::size_t>(j) * static_cast<std::size_t>(nu_) +
            static_cast<std::size_t>(i)] =
          static_cast<float>(source.intensity(texel_direction(i, j, nu_, nv_)));
}

DistributionTexture::DistributionTexture(int c_cells, int gamma_cells, std::vector<float> texels,
                                         Interpolation mode)
    : nu_(c_cells), nv_(gamma_cells), mode_(mode), data_(std::move(texels)) {
  check_resolution(nu_, nv_);
  if (data_.size() != static_cast<std::size_t>(nu_) * static_cast<std::size_t>(nv_ + 1))
    throw CalculationError("DistributionTexture: texel count does not match the resolution");
}

namespace {
// DistributionTexture::bilinear_batch on the texels: the texel positions of a chunk first, in a
// loop without branches that the compiler turns into vector instructions (texel_position, the
// template bilinear() takes for one direction), then the texels are read (cell_at, bilinear_in,
// bilinear()'s too), so the same values to the last bit.
LUXGRID_LANE void bilinear_batch_kernel(const float* texels, int nu, int nv, const double* x,
                                        const double* y, const double* z, int n, double* out) {
  // Chunks whose coordinates stay in L1 between the two loops.
  constexpr int kChunk = 64;
  double fu[kChunk], fv[kChunk];
  for (int begin = 0; begin < n; begin += kChunk) {
    const int m = std::min(kChunk, n - begin);
    for (int k = 0; k < m; ++k)
      texel_position(x[begin + k], y[begin + k], z[begin + k], nu, nv, fu[k], fv[k]);
    for (int k = 0; k < m; ++k)
      out[begin + k] = DistributionTexture::bilinear_in(
          texels, nu, DistributionTexture::cell_at(fu[k], fv[k], nu, nv));
  }
}
}  // namespace

LUXGRID_MULTIVERSION(void, bilinear_batch_texels,
                     (const float* texels, int nu, int nv, const double* x, const double* y,
                      const double* z, int n, double* out),
                     (texels, nu, nv, x, y, z, n, out), bilinear_batch_kernel)

void DistributionTexture::bilinear_batch(const double* x, const double* y, const double* z, int n,
                                         double* out) const {
  bilinear_batch_texels(data_.data(), nu_, nv_, x, y, z, n, out);
}

double DistributionTexture::intensity(const Vec3& d) const {
  if (mode_ == Interpolation::bilinear) return bilinear(d);
  const auto [i, j, i1, su, sv] = cell_of(d);
  double wu[4], wv[4];
  catmull_rom(su, wu);
  catmull_rom(sv, wv);
  const int cols[4] = {i == 0 ? nu_ - 1 : i - 1, i, i1, i1 + 1 == nu_ ? 0 : i1 + 1};
  double sum = 0.0;
  for (int r = 0; r < 4; ++r) {
    // Beyond the poles the rows are clamped (a pole row is constant, so this is exact there).
    const int row = std::clamp(j - 1 + r, 0, nv_);
    double s = 0.0;
    for (int c = 0; c < 4; ++c) s += wu[c] * texel(cols[c], row);
    sum += wv[r] * s;
  }
  return sum > 0.0 ? sum : 0.0;
}

}  // namespace luxgrid::photometry
