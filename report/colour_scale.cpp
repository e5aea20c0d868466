#include "report/colour_scale.h"

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
std::vector<double> ticks_for(double min, double max) {
  const double step = nice_ceil((max - min) / 5.0);
  std::vector<double> t;
  for (double v = std::ceil(min / step) * step; v <= max * (1 + 1e-9); v += step) t.push_back(v);
  return t;
}
}  // namespace

ColourScale auto_scale(double emax) {
  ColourScale s;
  s.min = 0.0;
  s.max = emax > 0.0 ? nice_ceil(emax) : 1.0;
  s.ticks = ticks_for(s.min, s.max);
  return s;
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
    if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v)) throw bad("\"" + s + "\" is not a number");
    return v;
  };
  const double lo = number(a), hi = number(b);
  if (lo < 0.0) throw bad("MIN must be >= 0 lx");
  if (!(lo < hi)) throw bad("MIN must be less than MAX");
  return fixed_scale(lo, hi);
}

}  // namespace luxgrid::report
