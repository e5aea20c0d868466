#include "report/colour_scale.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "util/error.h"

namespace luxgrid::report {

double nice_ceil(double x) {
  if (!(x > 0.0)) return 1.0;
  const double p = std::pow(10.0, std::floor(std::log10(x)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    // 1e-9 relative slack so 500 stays 500 and not 1000 after rounding noise.
    if (m * p >= x * (1.0 - 1e-9)) return m * p;
  }
  return 10.0 * p;
}

namespace {
std::vector<double> ticks_every(double min, double max, double step) {
  std::vector<double> t;
  // Multiples of step by index (not by repeated addition, which drifts: 0.1 + 0.2 != 0.3).
  for (long k = static_cast<long>(std::ceil(min / step - 1e-9));
       k * step <= max * (1 + 1e-9) + 1e-12; ++k)
    t.push_back(k * step);
  return t;
}
std::vector<double> ticks_for(double min, double max) {
  return ticks_every(min, max, nice_ceil((max - min) / 5.0));
}
}  // namespace

ColourScale auto_scale(double emax) {
  ColourScale s;
  s.min = 0.0;
  s.max = emax > 0.0 ? nice_ceil(emax) : 1.0;
  s.ticks = ticks_for(s.min, s.max);
  return s;
}

ColourScale fit_scale(double emin, double emax) {
  if (!(emax > 0.0) || !std::isfinite(emax)) return auto_scale(0.0);
  emin = std::isfinite(emin) ? std::clamp(emin, 0.0, emax) : 0.0;
  double range = emax - emin;
  if (range < 1e-6 * emax) {  // constant: centre a 10 % window on the value
    range = 0.1 * emax;
    emin = std::max(0.0, emin - range / 2);
    emax = emin + range;
  }
  // Candidate steps from range / 8 upwards through the 1, 2, 2.5, 5 sequence; the tightest
  // range with 3..8 intervals wins (ties: the larger step, fewer ticks).
  ColourScale best;
  double best_range = INFINITY;
  for (double step = nice_ceil(range / 8.0), k = 0; k < 8; ++k, step = nice_ceil(step * 1.0001)) {
    // k * step may land an ulp beyond the data (3 * 0.1 = 0.30000000000000004): the data wins.
    const double lo = std::min(emin, std::floor(emin / step * (1 + 1e-12)) * step);
    const double hi = std::max(emax, std::ceil(emax / step * (1 - 1e-12)) * step);
    const double n = std::round((hi - lo) / step);
    if (n < 3 || n > 8) continue;
    if (hi - lo <= best_range) {
      best_range = hi - lo;
      best = ColourScale{lo, hi, ticks_every(lo, hi, step)};
    }
  }
  if (!std::isfinite(best_range)) best = fixed_scale(0.0, nice_ceil(emax));
  return best;
}

ColourScale fixed_scale(double min, double max) {
  ColourScale s{min, max, {}};
  s.ticks = ticks_for(min, max);
  return s;
}

ColourScale parse_scale(const std::string& text) {
  const auto bad = [&](const std::string& why) {
    return InputError("--scale " + text + ": " + why);
  };
  const auto colon = text.find(':');
  if (colon == std::string::npos) throw bad("expected MIN:MAX in lux, e.g. 0:1000");
  const std::string a = text.substr(0, colon), b = text.substr(colon + 1);
  auto number = [&](const std::string& s) {
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v))
      throw bad("\"" + s + "\" is not a number");
    return v;
  };
  const double lo = number(a), hi = number(b);
  if (lo < 0.0) throw bad("MIN must be >= 0 lx");
  if (!(lo < hi)) throw bad("MIN must be less than MAX");
  return fixed_scale(lo, hi);
}

}  // namespace luxgrid::report
