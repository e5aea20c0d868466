#pragma once
// Shared set-ups for the near-field tests: the paper's 1 x 1 emitter (Luksch et al. 2020 Sec. 6)
// over a ground plane, at a height and an orientation.
#include <cmath>
#include <memory>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>

#include "calc/nearfield/analytic_profiles.h"
#include "calc/nearfield/emitter.h"
#include "photometry/builtin.h"

namespace luxgrid::nearfield::testing {

inline glm::dmat3 rotation_about_y(double angle_rad) {
  return glm::dmat3(glm::rotate(glm::dmat4(1.0), angle_rad, Vec3(0.0, 1.0, 0.0)));
}

// Emitter of size a x b centred at (0, 0, h), its emitting normal at angle `theta` from the
// ground normal +z (theta = pi: facing straight down, the paper's orientation pi).
inline Emitter paper_emitter(double h, double theta, photometry::DistributionPtr dist,
                             double a = 1.0, double b = 1.0) {
  photometry::LuminousOpening o;
  o.shape = photometry::LuminousOpening::Shape::rectangle;
  o.length = a;
  o.width = b;
  // Identity emits towards -z (theta = pi); turning about y by pi - theta tilts the normal.
  return make_emitter(o, Vec3(0.0, 0.0, h), rotation_about_y(kPi - theta), std::move(dist));
}

inline photometry::DistributionPtr lambertian(double i0 = 1000.0) {
  return std::make_shared<photometry::LambertianDistribution>(i0);
}
inline photometry::DistributionPtr isotropic(double i0 = 1000.0) {
  return std::make_shared<photometry::IsotropicDistribution>(i0);
}
inline photometry::DistributionPtr batwing(double i0 = 1000.0) {
  return std::make_shared<BatwingDistribution>(i0);
}
inline photometry::DistributionPtr spot(double i0 = 1000.0, double n = 20.0) {
  return std::make_shared<CosinePowerDistribution>(i0, n);
}

inline const Vec3 kUp{0.0, 0.0, 1.0};

}  // namespace luxgrid::nearfield::testing
