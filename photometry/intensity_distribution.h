#pragma once
// The one interface every emitter model uses: luminous intensity in candela for a direction in
// the luminaire's own frame. Frame (docs/photometry.md): gamma = 0 points to nadir (-z), C = 0
// along +x (the luminaire's length axis), C = 90 along +y.
#include <cstddef>
#include <memory>
#include <string>

#include "util/robust_math.h"
#include "util/table_angle.h"

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
  // intensity() of the n unit directions (x[k], y[k], z[k]) into out[k], the same values: a run
  // of look-ups at once (calc/nearfield/far_run.h: a point's far-field pairs), which a
  // distribution may do faster than one by one (TabularDistribution: the angles as lanes).
  virtual void intensities(const double* x, const double* y, const double* z, std::size_t n,
                           double* out) const {
    for (std::size_t k = 0; k < n; ++k) out[k] = intensity(Vec3(x[k], y[k], z[k]));
  }
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
// By the table angle (util/table_angle.h: atan2 to a few units in the last place, without a
// library call), in two parts for callers that need only gamma: every intensity look-up (the
// first bounce's pieces, the far-field pairs) and every near/far weight takes them. For a unit
// direction (the interface's contract) (h, -z) is a unit pair, and so is (|y|, x) / h; anything
// else (a direction of another length, the vertical, underflow) takes atan2 inside arc_angle or
// here. `horizontal` = sqrt(x^2 + y^2).
inline double gamma_of(double horizontal, double z) { return arc_angle(horizontal, -z); }
inline double c_of(double x, double y, double horizontal) {
  double c;
  if (horizontal > 0.0) {
    const double inv_h = 1.0 / horizontal;
    const double a = arc_angle(std::abs(y) * inv_h, x * inv_h);
    c = y < 0.0 ? 2.0 * kPi - a : a;
  } else {
    c = std::atan2(y, x);
    if (c < 0.0) c += 2.0 * kPi;
  }
  return c < 2.0 * kPi ? c : 0.0;
}
inline PhotometricAngles angles_of(const Vec3& d) {
  const double horizontal = std::sqrt(d.x * d.x + d.y * d.y);
  return {c_of(d.x, d.y, horizontal), gamma_of(horizontal, d.z)};
}
// angles_of for lanes (T = double or simd::D4: four directions at once, for calc/nearfield's
// near/far weights of a run of pairs): the table branch of c_of and gamma_of, the same operations
// in the same order, so the same bits in every lane where the returned mask holds (a horizontal
// part > 0 and both pairs of unit length: every unit direction but the vertical). Elsewhere the
// lane's values are not angles_of's: the caller takes angles_of for it.
template <class T>
LUXGRID_LANE simd::Mask<T> table_angles_of(const T& x, const T& y, const T& z, T& c, T& gamma) {
  const T horizontal = simd::sqrt(x * x + y * y);
  const T inv_h = 1.0 / horizontal;
  const T sin_c = simd::abs(y) * inv_h, cos_c = x * inv_h;
  const T r2_c = sin_c * sin_c + cos_c * cos_c;
  const T a = unit_pair_angle(sin_c, cos_c, r2_c);
  const T c_full = simd::select(y < 0.0, 2.0 * kPi - a, a);
  c = simd::select(c_full < 2.0 * kPi, c_full, simd::splat<T>(0.0));
  const T cos_g = -z;
  const T r2_g = horizontal * horizontal + cos_g * cos_g;
  gamma = unit_pair_angle(horizontal, cos_g, r2_g);
  return simd::logical_and(horizontal > 0.0, simd::logical_and(is_unit_pair(sin_c, r2_c),
                                                               is_unit_pair(horizontal, r2_g)));
}
Vec3 direction_of(double c, double gamma);

}  // namespace luxgrid::photometry
