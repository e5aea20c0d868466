#pragma once
// Analytic distributions for validation cases (project-format.md: "builtin").
#include "photometry/intensity_distribution.h"

namespace luxgrid::photometry {

// I0 in every direction.
class IsotropicDistribution final : public IntensityDistribution {
 public:
  explicit IsotropicDistribution(double i0) : i0_(i0) {}
  double intensity(const Vec3&) const override { return i0_; }
  double i0() const { return i0_; }

 private:
  double i0_;
};

// I0 cos(gamma) below the luminaire (towards -z), 0 above: a flat Lambertian emitter.
class LambertianDistribution final : public IntensityDistribution {
 public:
  explicit LambertianDistribution(double i0) : i0_(i0) {}
  double intensity(const Vec3& d) const override { return d.z < 0.0 ? -d.z * i0_ : 0.0; }
  double i0() const { return i0_; }

 private:
  double i0_;
};

}  // namespace luxgrid::photometry
