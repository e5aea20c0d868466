#pragma once
// A "light distribution texture" ([Wallner, Sec. 4]): the distribution resampled once on
// a regular grid, so that a lookup is a few multiplications and no search.
//
// Wallner indexes his texture by (C, gamma), which costs two inverse trigonometric calls per
// lookup. This texture is indexed by two *diamond angles* instead, computed from the direction
// with additions and one division each (plus a square root):
//   u = diamond angle of (x, y), in [0, 4): 0 at C0, 1 at C90, 2 at C180, 3 at C270
//   v = diamond angle of (h, -z) with h = |(x, y)|, in [0, 2]: 0 at nadir, 1 at the horizon
// Both are monotonic in the true angles; the grid is regular in (u, v), so its angular spacing
// varies by at most a factor of 2 (finest at the axes, coarsest at 45 deg). Texels are sampled
// from the source distribution at their exact directions.
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

  double intensity(const Vec3& direction) const override;
  Interpolation interpolation() const { return mode_; }
  int c_cells() const { return nu_; }
  int gamma_cells() const { return nv_; }

  // The texture coordinates (diamond angles) of a direction and back.
  static void diamond_angles(const Vec3& d, double& u, double& v);
  static Vec3 direction_of_diamond(double u, double v);

 private:
  double texel(int i, int j) const {
    return data_[static_cast<std::size_t>(j) * static_cast<std::size_t>(nu_) +
                 static_cast<std::size_t>(i)];
  }
  int nu_, nv_;
  Interpolation mode_;
  std::vector<float> data_;  // row-major by v; float halves the memory, error ~1e-7 relative
};

}  // namespace luxgrid::photometry
