#pragma once
// Sky luminance distributions relative to the zenith: the 15 CIE standard general skies
// [ISO15469] (gradation phi and indicatrix f with their a-e coefficients), the traditional CIE
// overcast sky (Moon and Spencer, L = L_z (1 + 2 sin h) / 3 [MoonSpencer1942]) and the uniform
// sky. Directions are unit vectors in the scene frame (z up); the sun's direction shapes the
// general skies only (its direct light is no part of the sky).
#include <optional>
#include <string>

#include "util/robust_math.h"

namespace luxgrid::daylight {

enum class SkyKind { cie_general, cie_overcast, uniform };

// The five coefficients of a CIE standard general sky [ISO15469, Tables 1 and 2].
struct CieSkyCoefficients {
  double a, b, c, d, e;
};
inline constexpr int kCieGeneralSkyTypes = 15;
// Type 1..15; throws std::out_of_range outside.
const CieSkyCoefficients& cie_sky_coefficients(int type);

// Gradation phi(Z) = 1 + a exp(b / cos Z), with phi = 1 at and below the horizon (cos Z <= 0,
// where exp(b / cos Z) -> 0 for b < 0) [ISO15469, Eq. 2].
double gradation(double cos_zenith, double a, double b);
// Indicatrix f(chi) = 1 + c [exp(d chi) - exp(d pi / 2)] + e cos^2 chi, chi the angle (rad) to
// the sun [ISO15469, Eq. 3].
double indicatrix(double chi_rad, double c, double d, double e);

struct SkyModel {
  SkyKind kind = SkyKind::uniform;
  int cie_type = 0;   // 1..15 for cie_general
  Vec3 sun{0, 0, 1};  // unit vector toward the sun (scene frame), for cie_general
  // "1".."15", "cie-overcast", "uniform": the name a project file gives.
  std::string name() const;
};

// The sky named as a project file names it ("cie-overcast", "uniform", or the type 1..15 as a
// number), or nothing for an unknown name.
std::optional<SkyModel> sky_from_name(const std::string& name);

// L(direction) / L_z for a direction above the horizon (direction.z > 0); 0 below it.
// The general sky: f(chi) phi(Z) / (f(Z_s) phi(0)) [ISO15469, Eq. 1].
double relative_luminance(const SkyModel& sky, const Vec3& direction);

}  // namespace luxgrid::daylight
