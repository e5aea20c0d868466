#pragma once
// A distribution without its table: asked per direction, as any analytic one is. Tests compare
// the code paths that read a type C table at their own angles with the general one through it.
#include "photometry/intensity_distribution.h"

namespace luxgrid::calc {

class Opaque final : public photometry::IntensityDistribution {
 public:
  explicit Opaque(const photometry::IntensityDistribution& d) : d_(d) {}
  double intensity(const Vec3& direction) const override { return d_.intensity(direction); }

 private:
  const photometry::IntensityDistribution& d_;
};

}  // namespace luxgrid::calc
