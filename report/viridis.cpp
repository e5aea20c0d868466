#include "report/viridis.h"

#include <bit>
#include <cmath>
#include <cstdint>

namespace luxgrid::report {

namespace {

Rgb8 exact(double t) { return Raster::to_bytes(viridis(t)); }

// The first t in (lo, hi] whose colour differs from lo's, given that hi's does and that the
// colour changes at most once from run to run (below): a bisection over the doubles, which
// for t > 0 are ordered as their bit patterns.
double first_change(double lo, double hi) {
  const Rgb8 from = exact(lo);
  auto lo_bits = std::bit_cast<std::uint64_t>(lo), hi_bits = std::bit_cast<std::uint64_t>(hi);
  while (hi_bits - lo_bits > 1) {
    const std::uint64_t mid = lo_bits + (hi_bits - lo_bits) / 2;
    (exact(std::bit_cast<double>(mid)) == from ? lo_bits : hi_bits) = mid;
  }
  return std::bit_cast<double>(hi_bits);
}

}  // namespace

const ViridisBytes& ViridisBytes::get() {
  static const ViridisBytes table;
  return table;
}

// Within a bucket (one knot interval) each channel of viridis(t), rounded to a byte, is a
// monotone function of t: t 16 - k is exact, and the float conversion, the product by the
// knots' difference, the sum and the rounding are each monotone. So a bucket's colours are runs
// that never return to an earlier colour, and the first t of each run is found exactly.
ViridisBytes::ViridisBytes() : low_(exact(0.0)), high_(exact(1.0)) {
  first_.reserve(kBuckets + 1);
  for (int b = 0; b < kBuckets; ++b) {
    first_.push_back(static_cast<std::uint32_t>(start_.size()));
    // The bucket's smallest and largest t (t > 0: t <= 0 never reaches the table).
    double lo = b == 0 ? std::nextafter(0.0, 1.0) : static_cast<double>(b) / kBuckets;
    const double hi = std::nextafter(static_cast<double>(b + 1) / kBuckets, 0.0);
    start_.push_back(lo), colour_.push_back(exact(lo));
    while (exact(hi) != colour_.back()) {
      lo = first_change(lo, hi);
      start_.push_back(lo), colour_.push_back(exact(lo));
    }
  }
  first_.push_back(static_cast<std::uint32_t>(start_.size()));
}

}  // namespace luxgrid::report
