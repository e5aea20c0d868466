#include "calc/nearfield/far_run.h"

#include <algorithm>

#include "calc/nearfield/models.h"

namespace luxgrid::nearfield {
namespace {
// Pairs per pass: the buffers on the stack.
constexpr std::size_t kFarPairsRun = 64;
}  // namespace

void far_field_pairs(const Emitter* const* emitters, std::size_t count, const Vec3& point,
                     const Vec3& normal, double* out) {
  const Receiver receiver = Receiver::planar(normal);
  double x[kFarPairsRun], y[kFarPairsRun], z[kFarPairsRun], cd[kFarPairsRun];
  double d2[kFarPairsRun], weight[kFarPairsRun];
  for (std::size_t begin = 0; begin < count; begin += kFarPairsRun) {
    const std::size_t n = std::min(kFarPairsRun, count - begin);
    const Emitter* const* run = emitters + begin;
    for (std::size_t k = 0; k < n; ++k) {
      const Emitter& e = *run[k];
      const FarPair p = far_pair(e.centroid, point, receiver);
      d2[k] = p.d2, weight[k] = p.weight;
      // The unit direction point_source_illuminance looks up; a pair it does not look up (at the
      // source, or behind the receiver) looks up the nadir instead, whose value is not used.
      const Vec3 local =
          far_pair_lit(p.d2, p.weight) ? (e.world_to_local * -p.r) * p.inv_d : Vec3(0, 0, -1);
      x[k] = local.x, y[k] = local.y, z[k] = local.z;
    }
    for (std::size_t a = 0; a < n;) {
      const photometry::IntensityDistribution& lookup = run[a]->far_lookup();
      std::size_t b = a + 1;
      while (b < n && &run[b]->far_lookup() == &lookup) ++b;
      lookup.intensities(x + a, y + a, z + a, b - a, cd + a);
      a = b;
    }
    for (std::size_t k = 0; k < n; ++k)
      out[begin + k] =
          far_pair_lit(d2[k], weight[k]) ? far_pair_illuminance(cd[k], weight[k], d2[k]) : 0.0;
  }
}

}  // namespace luxgrid::nearfield
