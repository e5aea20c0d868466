#pragma once
// Colour scales for illuminance plots: a range in lux rounded to values people read, and ticks.
#include <string>
#include <vector>

namespace luxgrid::report {

struct ColourScale {
  double min = 0.0, max = 1.0;  // lx
  std::vector<double> ticks;    // round values in [min, max]
};

// The smallest "nice" number (1, 2, 2.5, 5 x 10^k) >= x.
double nice_ceil(double x);

// 0 to a nice value above `emax` (an all-dark surface gets 0..1 lx), ticks every nice step.
ColourScale auto_scale(double emax);

// A scale fitted to data in [emin, emax]: round limits at the nearest multiples of a round step
// (1, 2, 2.5 or 5 x 10^k) below emin and above emax, the step chosen so the legend has 3 to 8
// intervals and the range is as tight as possible (534-622 lx gives 525-625 lx in steps of 25).
// A constant surface gets a range of about 10 % around its value; an all-dark one 0..1 lx.
ColourScale fit_scale(double emin, double emax);
ColourScale fixed_scale(double min, double max);

// Where `lx` lies on the scale, 0 at min to 1 at max, clamped: the argument of the colour map
// (report/viridis.h) as the maps use it.
inline double scale_position(const ColourScale& s, double lx) {
  const double t = (lx - s.min) / (s.max - s.min);
  return t > 0.0 ? (t < 1.0 ? t : 1.0) : 0.0;
}

// "MIN:MAX" in lux (the --scale option) -> a fixed scale. Throws InputError naming the text when
// it is not two finite numbers with 0 <= MIN < MAX.
ColourScale parse_scale(const std::string& text);

}  // namespace luxgrid::report
