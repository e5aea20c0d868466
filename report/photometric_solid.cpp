#include "report/photometric_solid.h"

#include <algorithm>

namespace luxgrid::report {

double PhotometricSolid::max_cd() const {
  return cd.empty() ? 0.0 : *std::max_element(cd.begin(), cd.end());
}

Vec3 solid_direction(int c, int gamma) {
  return photometry::direction_of(c * kSolidCStepDeg * kDegToRad,
                                  gamma * kSolidGammaStepDeg * kDegToRad);
}

PhotometricSolid photometric_solid(const photometry::IntensityDistribution& d) {
  PhotometricSolid s;
  s.cd.reserve(kSolidCPlanes * kSolidGammas);
  for (int c = 0; c < kSolidCPlanes; ++c)
    for (int g = 0; g < kSolidGammas; ++g) s.cd.push_back(d.intensity(solid_direction(c, g)));
  return s;
}

}  // namespace luxgrid::report
