// The integral over an aperture (calc/daylight/aperture_integral.h): a constant weight gives
// Lambert's exact projected solid angle at once; a varying weight converges to an independent
// brute-force quadrature over the aperture's area (cos theta_r cos theta_s / r^2 dA) within its
// own error estimate; the clip keeps what lies in front of the receiver and on one side of the
// horizon.
#include <gtest/gtest.h>

#include <cmath>

#include "calc/daylight/aperture_integral.h"

namespace luxgrid::daylight {
namespace {

// A 1 x 1 m square in the plane z = 3 centred over (2, 2), as two triangles.
std::vector<Triangle3> roof_square() {
  const Vec3 a{1.5, 1.5, 3}, b{2.5, 1.5, 3}, c{2.5, 2.5, 3}, d{1.5, 2.5, 3};
  return {{a, b, c}, {a, c, d}};
}

// Brute force: the midpoint rule on 400 x 400 cells of the square, of
// w(dir) cos_r cos_s / r^2.
template <class W>
double brute_force(const Vec3& p, const Vec3& n, W w) {
  constexpr int kCells = 400;
  double sum = 0.0;
  for (int i = 0; i < kCells; ++i)
    for (int j = 0; j < kCells; ++j) {
      const Vec3 x{1.5 + (i + 0.5) / kCells, 1.5 + (j + 0.5) / kCells, 3.0};
      const Vec3 d = x - p;
      const double r2 = glm::dot(d, d), r = std::sqrt(r2);
      const double cos_r = glm::dot(d, n) / r, cos_s = d.z / r;
      if (cos_r > 0.0) sum += w(d / r) * cos_r * cos_s / r2;
    }
  return sum / (kCells * kCells);
}

TEST(ApertureIntegral, ConstantIsLambertExactly) {
  const Vec3 p{2, 2, 0}, n{0, 0, 1};
  const double omega = aperture_projected_solid_angle(roof_square(), p, n);
  const ApertureIntegral r = integrate_aperture(
      roof_square(), p, n, [](const Vec3&, const Vec3&) { return 1.0; }, 1e-6, 0.0, 1000);
  EXPECT_NEAR(r.value, omega, 1e-15);
  EXPECT_LT(r.error_estimate, 1e-15);
  EXPECT_EQ(r.triangles, 2);  // no refinement
  // Against the brute force (its midpoint error about 1e-6 relative here).
  EXPECT_NEAR(omega, brute_force(p, n, [](const Vec3&) { return 1.0; }), 1e-5 * omega);
}

// w = (1 + 2 cos Z) / 3 (the overcast sky's gradation) seen from a tilted receiver off-centre:
// the adaptive value meets the brute force within 1e-4 relative when asked for 1e-5.
TEST(ApertureIntegral, VaryingWeightConverges) {
  const Vec3 p{0.5, 3.5, 1.0}, n = glm::normalize(Vec3{0.3, -0.4, 1.0});
  const auto overcast = [](const Vec3& d) { return (1.0 + 2.0 * d.z) / 3.0; };
  const ApertureIntegral r = integrate_aperture(
      roof_square(), p, n, [&](const Vec3&, const Vec3& d) { return overcast(d); }, 1e-5, 0.0,
      100000);
  const double reference = brute_force(p, n, overcast);
  EXPECT_NEAR(r.value, reference, 1e-4 * reference);
  EXPECT_LE(r.error_estimate, 1e-5 * r.value);
  EXPECT_GT(r.triangles, 2);
}

// The clip: a facade square x in [1, 3], z in [1, 2] at y = 0, seen from (2, 2, 1.5) facing -y:
// half above the horizon, half below, the two halves' projected solid angles add up to the whole.
TEST(ApertureIntegral, ClipSplitsAtTheHorizon) {
  const Vec3 a{1, 0, 1}, b{3, 0, 1}, c{3, 0, 2}, d{1, 0, 2};
  const std::vector<Triangle3> window{{a, b, c}, {a, c, d}};
  const Vec3 p{2, 2, 1.5}, n{0, -1, 0};
  const double whole = aperture_projected_solid_angle(window, p, n);
  const auto up = clip_to_receiver(window, p, n, true);
  const auto down = clip_to_receiver(window, p, n, false);
  const double above = aperture_projected_solid_angle(up, p, n);
  const double below = aperture_projected_solid_angle(down, p, n);
  EXPECT_NEAR(above + below, whole, 1e-14);
  EXPECT_NEAR(above, below, 1e-14);  // symmetric about the point's height
  for (const auto& t : up)
    for (const auto& v : t) EXPECT_GE(v.z, 1.5 - 1e-15);
  // Facing away, nothing is in front.
  EXPECT_TRUE(clip_to_receiver(window, p, Vec3{0, 1, 0}, true).empty());
}

}  // namespace
}  // namespace luxgrid::daylight
