#include "calc/daylight/sky_luminance.h"

#include <array>
#include <cmath>
#include <stdexcept>

namespace luxgrid::daylight {
namespace {

// [ISO15469, Table 1 (gradation a, b) and Table 2 (indicatrix c, d, e)], combined as the
// standard's Table 3 lists the 15 skies; the same values as colour-science's cie2003.py and TU
// Berlin's LightingToolbox (docs/daylight.md).
constexpr std::array<CieSkyCoefficients, kCieGeneralSkyTypes> kCoefficients{{
    {4.0, -0.70, 0.0, -1.0, 0.00},    // 1
    {4.0, -0.70, 2.0, -1.5, 0.15},    // 2
    {1.1, -0.80, 0.0, -1.0, 0.00},    // 3
    {1.1, -0.80, 2.0, -1.5, 0.15},    // 4
    {0.0, -1.00, 0.0, -1.0, 0.00},    // 5
    {0.0, -1.00, 2.0, -1.5, 0.15},    // 6
    {0.0, -1.00, 5.0, -2.5, 0.30},    // 7
    {0.0, -1.00, 10.0, -3.0, 0.45},   // 8
    {-1.0, -0.55, 2.0, -1.5, 0.15},   // 9
    {-1.0, -0.55, 5.0, -2.5, 0.30},   // 10
    {-1.0, -0.55, 10.0, -3.0, 0.45},  // 11
    {-1.0, -0.32, 10.0, -3.0, 0.45},  // 12
    {-1.0, -0.32, 16.0, -3.0, 0.30},  // 13
    {-1.0, -0.15, 16.0, -3.0, 0.30},  // 14
    {-1.0, -0.15, 24.0, -2.8, 0.15},  // 15
}};

}  // namespace

const CieSkyCoefficients& cie_sky_coefficients(int type) {
  if (type < 1 || type > kCieGeneralSkyTypes)
    throw std::out_of_range("CIE general sky type outside 1..15");
  return kCoefficients[type - 1];
}

double gradation(double cos_zenith, double a, double b) {
  if (!(cos_zenith > 0.0)) return 1.0;
  return 1.0 + a * std::exp(b / cos_zenith);
}

double indicatrix(double chi_rad, double c, double d, double e) {
  const double cos_chi = std::cos(chi_rad);
  return 1.0 + c * (std::exp(d * chi_rad) - std::exp(d * kPi / 2.0)) + e * cos_chi * cos_chi;
}

std::string SkyModel::name() const {
  switch (kind) {
    case SkyKind::cie_general: return std::to_string(cie_type);
    case SkyKind::cie_overcast: return "cie-overcast";
    case SkyKind::uniform: return "uniform";
  }
  return "";
}

std::optional<SkyModel> sky_from_name(const std::string& name) {
  SkyModel sky;
  if (name == "cie-overcast") {
    sky.kind = SkyKind::cie_overcast;
    return sky;
  }
  if (name == "uniform") return sky;
  for (int type = 1; type <= kCieGeneralSkyTypes; ++type)
    if (name == std::to_string(type)) {
      sky.kind = SkyKind::cie_general, sky.cie_type = type;
      return sky;
    }
  return std::nullopt;
}

double relative_luminance(const SkyModel& sky, const Vec3& direction) {
  const double cos_zenith = direction.z;
  if (!(cos_zenith > 0.0)) return 0.0;
  switch (sky.kind) {
    case SkyKind::uniform: return 1.0;
    case SkyKind::cie_overcast: return (1.0 + 2.0 * cos_zenith) / 3.0;  // sin h = cos Z
    case SkyKind::cie_general: {
      const CieSkyCoefficients& k = cie_sky_coefficients(sky.cie_type);
      const double chi = angle_between(direction, sky.sun);
      const double sun_zenith = angle_between(Vec3{0, 0, 1}, sky.sun);
      return indicatrix(chi, k.c, k.d, k.e) * gradation(cos_zenith, k.a, k.b) /
             (indicatrix(sun_zenith, k.c, k.d, k.e) * gradation(1.0, k.a, k.b));
    }
  }
  return 0.0;
}

}  // namespace luxgrid::daylight
