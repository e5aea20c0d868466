#pragma once
// IES LM-63 TILT data: how the lamp's output changes when the luminaire is tilted from the
// position it was measured in (HID lamps mostly). The candela table is for tilt 0; the calc
// module computes the actual tilt from the luminaire's pose and asks `factor(tilt)`.
#include <string>
#include <vector>

namespace luxgrid::photometry {

struct TiltTable {
  // LM-63 lamp-to-luminaire geometry: 1 = lamp vertical base up or down (tilt about any
  // horizontal axis), 2 = lamp horizontal along the C0-C180 axis (tilt turns it in the C0-C180
  // plane), 3 = lamp horizontal along the C90-C270 axis.
  int lamp_to_luminaire_geometry = 1;
  std::vector<double> angle_deg;  // ascending
  std::vector<double> factor;     // multiplying factor at each angle, >= 0
  std::string source;             // "INCLUDE" or the tilt file's path

  // Linear between the tabulated angles; |tilt| is used (LM-63 tabulates 0..90 or 0..180), and
  // beyond the last angle the last factor holds.
  double factor_at(double tilt_deg) const;
};

}  // namespace luxgrid::photometry
