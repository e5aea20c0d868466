#include "calc/scaled_distribution.h"

#include <array>
#include <cmath>
#include <vector>

#include <tbb/parallel_for.h>

#include "photometry/tabular_distribution.h"

namespace luxgrid::calc {

double luminous_flux(const photometry::IntensityDistribution& d) {
  // 8-point Gauss-Legendre per band of cos(gamma), 90 bands (2 degrees) and 360 C steps:
  // 259200 lookups, ~10 ms; sharp beams on 1-degree grids are still resolved.
  static constexpr std::array<double, 4> kNodes = {0.1834346424956498, 0.5255324099163290,
                                                   0.7966664774136267, 0.9602898564975363};
  static constexpr std::array<double, 4> kWeights = {0.3626837833783620, 0.3137066458778873,
                                                     0.2223810344533745, 0.1012285362903763};
  constexpr int kBands = 90, kCSteps = 360;
  // A type C table is read at the nodes' own angles (C = phi, gamma from the node), its C
  // positions found once: no trigonometry per lookup, the same values to rounding.
  const photometry::TableView view = d.table_view();
  std::vector<photometry::TabularDistribution::CPosition> c_of_step;
  if (view.table) {
    c_of_step.resize(kCSteps);
    for (int c = 0; c < kCSteps; ++c)
      c_of_step[c] = view.table->c_position((c + 0.5) * 2.0 * kPi / kCSteps);
  }
  // Bands in parallel, summed in order afterwards (the same total on any number of threads).
  std::array<double, kBands> band_total{};
  tbb::parallel_for(0, kBands, [&](int band) {
    double total = 0.0;
    const double lo = -1.0 + 2.0 * band / kBands, hi = -1.0 + 2.0 * (band + 1) / kBands;
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    for (int k = 0; k < 8; ++k) {
      const double x = mid + (k < 4 ? -1 : 1) * kNodes[k % 4] * half;  // x = -cos(gamma) = dir.z
      const double w = kWeights[k % 4] * half;
      const double s = std::sqrt(std::max(0.0, 1.0 - x * x));
      double ring = 0.0;
      std::size_t j = 0;
      double tg = 0.0;
      if (!view.table) {
        for (int c = 0; c < kCSteps; ++c) {
          const double phi = (c + 0.5) * 2.0 * kPi / kCSteps;
          ring += d.intensity(Vec3(s * std::cos(phi), s * std::sin(phi), x));
        }
      } else if (view.table->gamma_cell(std::atan2(s, -x), j, tg)) {  // gamma: 0 at nadir
        for (int c = 0; c < kCSteps; ++c)
          ring += view.scale * view.table->intensity_at(c_of_step[c], j, tg);
      }
      total += w * ring * (2.0 * kPi / kCSteps);
    }
    band_total[band] = total;
  });
  double total = 0.0;
  for (double t : band_total) total += t;
  return total;
}

}  // namespace luxgrid::calc
