#pragma once
// The one interface every emitter model uses: luminous intensity in candela for a direction in
// the luminaire's own frame. Frame (docs/photometry.md): gamma = 0 points to nadir (-z), C = 0
// along +x (the luminaire's length axis), C = 90 along +y.
#include <memory>
#include <string>

#include "util/robust_math.h"

namespace luxgrid::photometry {

class TabularDistribution;

// A measured table seen through any wrappers: intensity = scale x table lookup. Integrators use
// it to put their cell boundaries on the table's angles, where a bilinear or bicubic
// interpolant has its kinks (calc/nearfield/table_cubature.cpp).
struct TableView {
  const TabularDistribution* table = nullptr;  // nullptr: no table in the luminaire frame
  double scale = 1.0;
};

class IntensityDistribution {
 public:
  virtual ~IntensityDistribution() = default;
  // `direction` is a unit vector from the luminaire outward, in luminaire coordinates.
  // Returns a finite value >= 0 in cd (all multipliers and factors applied).
  virtual double intensity(const Vec3& direction) const = 0;
  // The table behind this distribution when its (C, gamma) are the luminaire frame's own
  // (type C photometry), else {nullptr}: analytic profiles, textures, type A/B tables.
  virtual TableView table_view() const { return {}; }
};

using DistributionPtr = std::shared_ptr<const IntensityDistribution>;

// Photometric angles of a direction in the luminaire frame, in radians:
// gamma in [0, pi] from nadir, c in [0, 2 pi) counter-clockwise from +x seen from above.
struct PhotometricAngles {
  double c;
  double gamma;
};
PhotometricAngles angles_of(const Vec3& direction);
Vec3 direction_of(double c, double gamma);

}  // namespace luxgrid::photometry
