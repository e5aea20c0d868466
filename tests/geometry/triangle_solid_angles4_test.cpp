#include "geometry/triangle_solid_angles4.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "geometry/spherical.h"

namespace luxgrid::geometry {
namespace {

// Four at once must give triangle_solid_angle_from's values to the bit (the first bounce does
// not change with it): triangles in front of and behind the point, slivers with two equal
// corners, the point on a corner (0 sr), and triangles seen under more than pi sr. Each version
// of the kernel (util/simd.h's LUXGRID_MULTIVERSION) is called by name.
using Four = void (*)(const Vec3&, const Vec3 (&)[4], const Vec3 (&)[4], const Vec3 (&)[4],
                      double (&)[4]);
void expect_same_bits_as_one_by_one(Four four_at_once) {
  std::mt19937_64 rng(612);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int differ = 0, nonzero = 0;
  constexpr int kRounds = 100000;
  for (int t = 0; t < kRounds; ++t) {
    Vec3 s(u(rng), u(rng), u(rng) + 2.0);
    if (t % 9 == 0) s = Vec3(0.0, 0.0, 0.01 * u(rng));  // close to the triangles' plane
    Vec3 a[4], b[4], c[4];
    for (int k = 0; k < 4; ++k) {
      a[k] = Vec3(u(rng), u(rng), 0.1 * u(rng));
      b[k] = a[k] + 0.3 * Vec3(u(rng), u(rng), u(rng));
      c[k] = a[k] + 0.3 * Vec3(u(rng), u(rng), u(rng));
      if ((t + k) % 17 == 0) c[k] = b[k];                         // a sliver
      if ((t + k) % 19 == 0) a[k] = s;                            // the point on a corner
      if ((t + k) % 23 == 0) c[k] = a[k] + 1e-9 * (b[k] - a[k]);  // a needle
    }
    double four[4];
    four_at_once(s, a, b, c, four);
    for (int k = 0; k < 4; ++k) {
      const double one = triangle_solid_angle_from(s, a[k], b[k], c[k]);
      if (std::memcmp(&one, &four[k], sizeof(double)) != 0) ++differ;
      if (one > 0.0) ++nonzero;
    }
  }
  EXPECT_EQ(differ, 0) << "of " << 4 * kRounds;
  EXPECT_GT(nonzero, 3 * kRounds);  // the cases are not all trivial
}

TEST(TriangleSolidAngles4, SameBitsAsOneByOneAvx2) {
  if (!simd::cpu_has_avx2()) GTEST_SKIP() << "this processor has no AVX2";
  expect_same_bits_as_one_by_one(triangle_solid_angles_from4_avx2);
}
TEST(TriangleSolidAngles4, SameBitsAsOneByOneDefault) {
  expect_same_bits_as_one_by_one(triangle_solid_angles_from4_default);
}

// The triangle through the three unit points on the axes, seen from the origin, spans one
// octant of the sphere: 4 pi / 8 sr. From far away along (1, 1, 1), facing it: its area over the
// distance squared, to the first neglected order (size / distance)^2, about 3e-7 here.
TEST(TriangleSolidAngles4, OctantAndLimits) {
  const Vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  const Vec3 a[4] = {x, x, x, x}, b[4] = {y, y, y, y}, c[4] = {z, z, z, z};
  double omega[4];
  triangle_solid_angles_from4(Vec3(0.0), a, b, c, omega);
  EXPECT_NEAR(omega[0], 0.5 * kPi, 1e-14);
  triangle_solid_angles_from4(Vec3(1e3), a, b, c, omega);
  // Area sqrt(3) / 2, its centroid (1, 1, 1) / 3 at distance sqrt(3) (1000 - 1 / 3).
  const double d = std::sqrt(3.0) * (1e3 - 1.0 / 3.0), point = std::sqrt(3.0) / 2.0 / (d * d);
  EXPECT_NEAR(omega[1], point, 1e-6 * point);
}

}  // namespace
}  // namespace luxgrid::geometry
