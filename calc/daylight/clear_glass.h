#pragma once
// Clear glass as Radiance's `glass` material models it [Ward-glass]: a pane of refractive index
// 1.52 whose normal transmittance T_n is given; unpolarised Fresnel reflection at both surfaces,
// the multiple reflections between them, and absorption over the path through the pane, which
// grows as 1 / cos of the refracted angle. The CIE 171 glazed cases (5.10, 5.12) are reproduced
// by it to about 1 % (docs/daylight.md).
namespace luxgrid::daylight {

inline constexpr double kGlassRefractiveIndex = 1.52;

class ClearGlass {
 public:
  // T_n in (0, 1], no more than a lossless pane of index 1.52 lets through (0.9183...).
  explicit ClearGlass(double normal_transmittance);
  // The pane's transmittance for light arriving at `cos_incidence` (|cos| of the angle to the
  // pane's normal, either side); T_n at normal incidence, 0 at grazing.
  double transmittance(double cos_incidence) const;
  // The internal transmissivity of one pass at normal incidence, solved from T_n.
  double normal_transmissivity() const { return transmissivity_; }
  double normal_transmittance() const { return normal_transmittance_; }

 private:
  double normal_transmittance_;
  double transmissivity_;
};

// The largest T_n a pane of index 1.52 can have: no absorption, (1 - r) / (1 + r) with r the
// normal reflectance ((n - 1) / (n + 1))^2.
double lossless_normal_transmittance();

}  // namespace luxgrid::daylight
