#include "geometry/quad_projected_solid_angle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "geometry/spherical.h"

namespace luxgrid::geometry {
namespace {

// The four edges at once must give projected_solid_angle's value to the bit (the gather's
// results do not change with it): parallelograms seen from above and across, nearly flat ones,
// the viewpoint almost on the patch, and a corner at the viewpoint (the scalar code's branch).
// Each version of the kernel (util/simd.h's LUXGRID_MULTIVERSION) is called by name.
void expect_same_bits_as_the_edges_one_by_one(double (*quad)(const Vec3*, const Vec3&)) {
  std::mt19937_64 rng(20261206);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int differ = 0, nonzero = 0;
  constexpr int kQuads = 200000;
  for (int t = 0; t < kQuads; ++t) {
    Vec3 x(u(rng), u(rng), 0.5 * u(rng) + 1.0);
    const Vec3 o(u(rng), u(rng), 0.1 * u(rng));
    const Vec3 e1(0.3 * u(rng), 0.3 * u(rng), 0.05 * u(rng));
    Vec3 e2(0.3 * u(rng), 0.3 * u(rng), 0.05 * u(rng));
    if (t % 7 == 0) e2 = 1e-9 * e1;                            // a sliver
    if (t % 11 == 0) x = o + 0.5 * e1 + Vec3(0.0, 0.0, 1e-7);  // almost on it
    if (t % 17 == 0) e2 = Vec3(0.0);                           // two corners on one point
    const Vec3 corners[4] = {o, o + e1, o + e1 + e2, o + e2};
    const Vec3 n = glm::normalize(Vec3(0.3 * u(rng), 0.3 * u(rng), -1.0));
    Vec3 rel[4];
    for (int k = 0; k < 4; ++k) rel[k] = corners[k] - x;
    if (t % 13 == 0) rel[2] = Vec3(0.0);  // a corner at the viewpoint
    const double edges = projected_solid_angle(rel, 4, n);
    const double four = quad(rel, n);
    if (std::memcmp(&edges, &four, sizeof(double)) != 0) ++differ;
    if (edges > 0.0) ++nonzero;
  }
  EXPECT_EQ(differ, 0) << "of " << kQuads;
  EXPECT_GT(nonzero, kQuads / 2);  // the cases are not all trivial
}

TEST(QuadProjectedSolidAngle, SameBitsAsTheEdgesOneByOneAvx2) {
  if (!simd::cpu_has_avx2()) GTEST_SKIP() << "this processor has no AVX2";
  expect_same_bits_as_the_edges_one_by_one(quad_projected_solid_angle_avx2);
}
TEST(QuadProjectedSolidAngle, SameBitsAsTheEdgesOneByOneDefault) {
  expect_same_bits_as_the_edges_one_by_one(quad_projected_solid_angle_default);
}

// A square of half side a at distance h, seen from the point on its axis with the normal along
// the axis: pi times the form factor to a coaxial parallel rectangle (Howell's catalogue, the
// point-to-rectangle factor of four corner rectangles), 4 a / r atan(a / r), r = sqrt(a^2 + h^2).
TEST(QuadProjectedSolidAngle, SquareOverItsCentre) {
  const double a = 0.5, h = 1.0;
  const Vec3 rel[4] = {{-a, -a, h}, {a, -a, h}, {a, a, h}, {-a, a, h}};
  const double r = std::sqrt(a * a + h * h);
  const double exact = 4.0 * a / r * std::atan(a / r);
  EXPECT_NEAR(quad_projected_solid_angle(rel, Vec3(0, 0, 1)), exact, 1e-14);
}

}  // namespace
}  // namespace luxgrid::geometry
