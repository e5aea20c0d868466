#pragma once
// Illuminance statistics of a calculation surface, as lighting standards define them.
#include <vector>

namespace luxgrid::calc {

struct Statistics {
  double Emin = 0.0, Eavg = 0.0, Emax = 0.0;
  double U0 = 0.0;  // Emin / Eavg (overall uniformity, EN 12464-1); 0 when Eavg is 0
  double Ud = 0.0;  // Emin / Emax (diversity); 0 when Emax is 0
};

// Over the points whose `active` flag is true (all when `active` is empty). An unweighted mean:
// grid points sit at the centres of equal cells, so it is the area average.
Statistics compute_statistics(const std::vector<double>& E, const std::vector<bool>& active = {});

}  // namespace luxgrid::calc
