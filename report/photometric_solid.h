#pragma once
// A luminaire's photometric solid as the 3D views draw it (scene.glb, report.html, `luxgrid
// view`): its intensity sampled on a grid of C planes and angles from nadir, so that the solid
// can be drawn from results.json alone, without the photometric file (docs/report.md).
#include <vector>

#include "photometry/intensity_distribution.h"

namespace luxgrid::report {

// The sampling: C = 0, 10, ..., 350 degrees and gamma = 0, 5, ..., 180 degrees, enough to show a
// beam's direction and width at a glance (it is a picture; the calculation uses the table).
inline constexpr int kSolidCPlanes = 36;
inline constexpr int kSolidGammas = 37;
inline constexpr double kSolidCStepDeg = 360.0 / kSolidCPlanes;
inline constexpr double kSolidGammaStepDeg = 180.0 / (kSolidGammas - 1);

struct PhotometricSolid {
  // Intensity in cd at C plane c and angle gamma from nadir: cd[c * kSolidGammas + gamma].
  std::vector<double> cd;
  double max_cd() const;
};

PhotometricSolid photometric_solid(const photometry::IntensityDistribution& d);

// The unit direction of sample (c, gamma) in the luminaire's frame (photometry::direction_of).
Vec3 solid_direction(int c, int gamma);

}  // namespace luxgrid::report
