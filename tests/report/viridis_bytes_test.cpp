// The plots colour their pixels from ViridisBytes' table: it must give Raster::to_bytes(viridis(t))
// for every t, not only most, or a picture would change. Checked around every place the bytes
// change (each found by bisection here, independently of the table's own search), at both sides
// of every bucket and knot boundary, at a million random t and at the special values.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "report/raster.h"
#include "report/viridis.h"

namespace luxgrid::report {
namespace {

Rgb8 exact(double t) { return Raster::to_bytes(viridis(t)); }

// t and the 3 doubles on either side of it, within [0, 1].
std::vector<double> around(double t) {
  std::vector<double> out;
  double below = t, above = t;
  out.push_back(t);
  for (int k = 0; k < 3; ++k) {
    below = std::nextafter(below, -1.0), above = std::nextafter(above, 2.0);
    out.push_back(below), out.push_back(above);
  }
  return out;
}

TEST(ViridisBytes, SameBytesAsRoundingTheColoursFloatsForEveryT) {
  const ViridisBytes& table = ViridisBytes::get();
  std::vector<double> ts = {0.0,
                            -0.0,
                            -1e-300,
                            -5.0,
                            1.0,
                            1.5,
                            INFINITY,
                            -INFINITY,
                            NAN,
                            std::numeric_limits<double>::denorm_min(),
                            1e-300,
                            0.5,
                            std::nextafter(1.0, 0.0)};
  // Both sides of every 1/65536 (the table's 4096 buckets and viridis' 16 knots among them).
  for (int k = 0; k <= 65536; ++k)
    for (double t : around(k / 65536.0)) ts.push_back(t);
  // Every change of colour along a sweep of 2^20 steps, found to the last bit by bisection.
  int changes = 0;
  constexpr int kSteps = 1 << 20;
  for (int k = 0; k < kSteps; ++k) {
    double lo = static_cast<double>(k) / kSteps, hi = static_cast<double>(k + 1) / kSteps;
    if (k == 0) lo = std::numeric_limits<double>::denorm_min();
    if (exact(lo) == exact(hi)) continue;
    ++changes;
    auto a = std::bit_cast<std::uint64_t>(lo), b = std::bit_cast<std::uint64_t>(hi);
    const Rgb8 from = exact(lo);
    while (b - a > 1) {
      const std::uint64_t mid = a + (b - a) / 2;
      (exact(std::bit_cast<double>(mid)) == from ? a : b) = mid;
    }
    for (double t : around(std::bit_cast<double>(b))) ts.push_back(t);
  }
  EXPECT_GT(changes, 600) << "the sweep found the colour's steps";
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int k = 0; k < 1000000; ++k) ts.push_back(uniform(rng));
  for (double t : ts) {
    const Rgb8 want = exact(t), got = table(t);
    ASSERT_EQ(got, want) << "t = " << t << " (" << std::hexfloat << t << ")";
  }
}

}  // namespace
}  // namespace luxgrid::report
