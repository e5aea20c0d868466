#pragma once
// The viridis colour map [vanderWaltSmith2015]: perceptually uniform and monotonic in lightness.
// Inline: a plot looks a colour up for each of its pixels.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "report/raster.h"

namespace luxgrid::report {

namespace viridis_detail {
// matplotlib's viridis table [vanderWaltSmith2015] at t = k / 16, in sRGB.
inline constexpr Rgb kKnots[17] = {
    {0.267004f, 0.004871f, 0.329414f}, {0.282326f, 0.094957f, 0.417331f},
    {0.278826f, 0.175489f, 0.483397f}, {0.258964f, 0.251538f, 0.524736f},
    {0.229740f, 0.322361f, 0.545706f}, {0.199429f, 0.387607f, 0.554642f},
    {0.172719f, 0.448791f, 0.557885f}, {0.149040f, 0.508051f, 0.557250f},
    {0.127567f, 0.566949f, 0.550557f}, {0.120636f, 0.625828f, 0.533488f},
    {0.157850f, 0.683765f, 0.501686f}, {0.246070f, 0.738910f, 0.452024f},
    {0.369214f, 0.788888f, 0.382914f}, {0.515992f, 0.831158f, 0.294279f},
    {0.678489f, 0.863742f, 0.189503f}, {0.845561f, 0.887322f, 0.099704f},
    {0.993248f, 0.906157f, 0.143934f},
};

}  // namespace viridis_detail

// sRGB colour at t in [0, 1] (clamped): linear interpolation between 17 knots of the map.
inline Rgb viridis(double t) {
  if (!(t > 0.0)) return viridis_detail::kKnots[0];
  if (t >= 1.0) return viridis_detail::kKnots[16];
  const double s = t * 16.0;
  // s > 0 here, so truncation is floor (without a call into libm: this runs once a pixel).
  const int k = std::min(15, static_cast<int>(s));
  const float f = static_cast<float>(s - k);
  const Rgb& a = viridis_detail::kKnots[k];
  const Rgb& b = viridis_detail::kKnots[k + 1];
  return {a.r + (b.r - a.r) * f, a.g + (b.g - a.g) * f, a.b + (b.b - a.b) * f};
}

// Raster::to_bytes(viridis(t)) for every t, bit for bit, from a table: a map colours each of its
// 10^5 pixels, and the bytes change only 684 times over [0, 1]. Made once, on the first get();
// the lookup is inline.
class ViridisBytes {
 public:
  static const ViridisBytes& get();

  Rgb8 operator()(double t) const {
    if (!(t > 0.0)) return low_;  // viridis() gives its first knot to t <= 0 and NaN
    if (t >= 1.0) return high_;
    // t kBuckets is exact (a power of two), and below kBuckets since t < 1.
    const int b = static_cast<int>(t * kBuckets);
    std::uint32_t e = first_[b];
    const std::uint32_t last = first_[b + 1] - 1;
    while (e < last && t >= start_[e + 1]) ++e;
    return colour_[e];
  }

 private:
  // [0, 1) cut into kBuckets equal buckets, a multiple of 16, so each lies within one knot
  // interval of viridis().
  static constexpr int kBuckets = 4096;
  ViridisBytes();
  Rgb8 low_, high_;
  // Bucket b's runs of one colour are entries first_[b] to first_[b + 1] - 1: run e holds from
  // t = start_[e] on.
  std::vector<std::uint32_t> first_;
  std::vector<double> start_;
  std::vector<Rgb8> colour_;
};

}  // namespace luxgrid::report
