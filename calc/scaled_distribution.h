#pragma once
// A distribution times a constant: the project file's `multiplier` and `flux_lm` rescaling.
#include "photometry/intensity_distribution.h"

namespace luxgrid::calc {

class ScaledDistribution final : public photometry::IntensityDistribution {
 public:
  ScaledDistribution(photometry::DistributionPtr inner, double factor)
      : inner_(std::move(inner)), factor_(factor) {}
  double intensity(const Vec3& d) const override { return factor_ * inner_->intensity(d); }
  void intensities(const double* x, const double* y, const double* z, std::size_t n,
                   double* out) const override {
    inner_->intensities(x, y, z, n, out);
    for (std::size_t k = 0; k < n; ++k) out[k] = factor_ * out[k];
  }
  photometry::TableView table_view() const override {
    photometry::TableView v = inner_->table_view();
    v.scale *= factor_;
    return v;
  }
  const photometry::DistributionPtr& inner() const { return inner_; }
  double factor() const { return factor_; }

 private:
  photometry::DistributionPtr inner_;
  double factor_;
};

// Total luminous flux of any distribution, lm: the integral of I over the sphere, by a
// product rule (Gauss-Legendre in cos(gamma), midpoint in C). For the tabulated files the
// photometry module's own integral is exact for its interpolant; this one serves any
// IntensityDistribution and agrees with it to ~1e-4 on smooth tables.
double luminous_flux(const photometry::IntensityDistribution& d);

}  // namespace luxgrid::calc
