#include "calc/statistics.h"

#include <algorithm>
#include <limits>

namespace luxgrid::calc {

Statistics compute_statistics(const std::vector<double>& E, const std::vector<bool>& active) {
  Statistics s;
  double sum = 0.0;
  size_t n = 0;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (size_t i = 0; i < E.size(); ++i) {
    if (!active.empty() && !active[i]) continue;
    sum += E[i];
    lo = std::min(lo, E[i]);
    hi = std::max(hi, E[i]);
    ++n;
  }
  if (n == 0) return s;
  s.Emin = lo;
  s.Emax = hi;
  s.Eavg = sum / static_cast<double>(n);
  s.U0 = s.Eavg > 0.0 ? s.Emin / s.Eavg : 0.0;
  s.Ud = s.Emax > 0.0 ? s.Emin / s.Emax : 0.0;
  return s;
}

}  // namespace luxgrid::calc
