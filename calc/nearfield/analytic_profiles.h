#pragma once
// Analytic intensity distributions for the near-field tests and the accuracy study, in the
// luminaire frame (gamma from nadir, -z). Lambertian and isotropic are in photometry/builtin.h.
#include <cmath>

#include "photometry/intensity_distribution.h"

namespace luxgrid::nearfield {

// Batwing: I0 cos(g) (1 + 2 sin^2 g) below, 0 above: the batwing data set of the accuracy study
// (docs/accuracy.md), whose peak off nadir the published cubature misses (docs/nearfield.md).
class BatwingDistribution final : public photometry::IntensityDistribution {
 public:
  explicit BatwingDistribution(double i0) : i0_(i0) {}
  double intensity(const Vec3& d) const override {
    if (!(d.z < 0.0)) return 0.0;
    const double c = -d.z;
    return i0_ * c * (1.0 + 2.0 * (1.0 - c * c));
  }

 private:
  double i0_;
};

// Peaked (spot-like): I0 cos^n(g) below, 0 above.
class CosinePowerDistribution final : public photometry::IntensityDistribution {
 public:
  CosinePowerDistribution(double i0, double n) : i0_(i0), n_(n) {}
  double intensity(const Vec3& d) const override {
    return d.z < 0.0 ? i0_ * std::pow(-d.z, n_) : 0.0;
  }

 private:
  double i0_, n_;
};

// A profile that is zero in a cone and in a half-space of C angles: tests "zero in some
// directions" (issue item 5). I0 cos(g) where gamma > 20 deg and the x component is >= 0.
class ZeroPatchDistribution final : public photometry::IntensityDistribution {
 public:
  explicit ZeroPatchDistribution(double i0) : i0_(i0) {}
  double intensity(const Vec3& d) const override {
    if (!(d.z < 0.0) || d.x < 0.0) return 0.0;
    return -d.z > std::cos(20.0 * 3.14159265358979323846 / 180.0) ? 0.0 : -d.z * i0_;
  }

 private:
  double i0_;
};

}  // namespace luxgrid::nearfield
