#pragma once
// Numbers derived from a distribution: luminous flux by integration over the sphere, downward
// flux fraction, light output ratio, maximum intensity and beam/field angles.
#include <optional>

#include "photometry/photometry.h"
#include "photometry/tabular_distribution.h"

namespace luxgrid::photometry {

struct BeamAngles {
  double beam_deg = 0.0;   // full angle in the plane between the 50 % points around the peak
  double field_deg = 0.0;  // the same at 10 %
};

struct DerivedPhotometry {
  double flux_lm = 0.0;           // integral of I over the sphere (the chosen interpolation)
  double downward_flux_lm = 0.0;  // part with direction z < 0 (gamma < 90 deg)
  double dff = 0.0;               // downward / total, 0..1 (0 for a dark table)
  std::optional<double> lor;      // flux / stated lamp flux; none for absolute photometry
  double max_cd = 0.0;
  double max_c_deg = 0.0, max_gamma_deg = 0.0;  // direction of max_cd, luminaire frame
  Vec3 max_direction{0.0, 0.0, -1.0};
  BeamAngles c0_c180;   // in the plane through C0 and C180
  BeamAngles c90_c270;  // in the plane through C90 and C270
};

// Integrates the interpolant itself (bilinear or bicubic, whichever the table uses) so that flux
// and lookups agree: per grid cell, Gauss-Legendre in C and in gamma with the sin(gamma) weight,
// cells cut at gamma = 90 deg (type C) or C' = 90/270 deg (types A, B) so the downward part is
// exact, and gamma pieces no wider than 2 deg so sin(gamma) is integrated to ~1e-13.
struct FluxResult {
  double total_lm = 0.0;
  double downward_lm = 0.0;
};
FluxResult integrate_flux(const TabularDistribution& table);

// DFF = downward / total (0 for a dark table) and LOR = total / stated lamp flux (none for
// absolute photometry): the one place these ratios are formed, for derive() and for the
// stated-versus-integrated check (file_warnings.h).
struct FluxRatios {
  double dff = 0.0;
  std::optional<double> lor;
};
FluxRatios flux_ratios(const Photometry& p, const FluxResult& flux);

// Beam (50 %) and field (10 %) angles in the vertical plane through C = c_deg and c_deg + 180,
// measured from the plane's peak outwards on both sides, sampled every 0.05 deg of the
// interpolant with linear interpolation of the crossing.
BeamAngles beam_angles(const IntensityDistribution& d, double c_deg);

DerivedPhotometry derive(const Photometry& p);

// Intensity in the plane C = c_deg (and C + 180 for negative angles) as a function of the
// signed angle from nadir, degrees in [-180, 180]: what a polar diagram draws.
double plane_intensity(const IntensityDistribution& d, double c_deg, double signed_gamma_deg);

}  // namespace luxgrid::photometry
