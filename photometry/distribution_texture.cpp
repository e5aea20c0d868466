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

void DistributionTexture::diamond_angles(const Vec3& d, double& u, double& v) {
  const double ax = std::abs(d.x), ay = std::abs(d.y);
  const double sxy = ax + ay;
  if (sxy > 0.0) {
    const double t = d.y / sxy;  // in [-1, 1]
    if (d.x >= 0.0)
      u = t >= 0.0 ? t : 4.0 + t;  // quadrants 1 and 4
    else
      u = 2.0 - t;  // quadrants 2 and 3
    if (u >= 4.0) u = 0.0;
  } else {
    u = 0.0;  // a pole: every column holds the same value there
  }
  const double h = std::sqrt(d.x * d.x + d.y * d.y);
  const double a = -d.z;
  const double s = h + std::abs(a);
  v = s > 0.0 ? (a >= 0.0 ? h / s : 2.0 - h / s) : 1.0;
}

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

DistributionTexture::DistributionTexture(const IntensityDistribution& source, int c_cells,
                                         int gamma_cells, Interpolation mode)
    : nu_(c_cells), nv_(gamma_cells), mode_(mode) {
  if (nu_ < 4 || nv_ < 2 || static_cast<long>(nu_) * (nv_ + 1) > 50'000'000L)
    throw CalculationError("DistributionTexture: resolution out of range");
  data_.resize(static_cast<std::size_t>(nu_) * static_cast<std::size_t>(nv_ + 1));
  for (int j = 0; j <= nv_; ++j) {
    const double v = 2.0 * j / nv_;
    for (int i = 0; i < nu_; ++i) {
      const double u = 4.0 * i / nu_;
      double value;
      if (j == 0 || j == nv_)  // a pole is one direction
        value = source.intensity({0.0, 0.0, j == 0 ? -1.0 : 1.0});
      else
        value = source.intensity(direction_of_diamond(u, v));
      data_[static_cast<std::size_t>(j) * static_cast<std::size_t>(nu_) +
            static_cast<std::size_t>(i)] = static_cast<float>(value);
    }
  }
}

double DistributionTexture::intensity(const Vec3& d) const {
  double u, v;
  diamond_angles(d, u, v);
  const double fu = u * (nu_ / 4.0), fv = v * (nv_ / 2.0);
  int i = static_cast<int>(fu), j = static_cast<int>(fv);
  if (i >= nu_) i = nu_ - 1;
  if (j >= nv_) j = nv_ - 1;
  const double su = fu - i, sv = fv - j;
  const int i1 = i + 1 == nu_ ? 0 : i + 1;
  if (mode_ == Interpolation::bilinear) {
    const double a = texel(i, j) + su * (texel(i1, j) - texel(i, j));
    const double b = texel(i, j + 1) + su * (texel(i1, j + 1) - texel(i, j + 1));
    return a + sv * (b - a);
  }
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
