#include "calc/daylight/en17037.h"

#include <algorithm>
#include <limits>

namespace luxgrid::daylight {

const char* to_string(En17037Level level) {
  switch (level) {
    case En17037Level::minimum: return "minimum";
    case En17037Level::medium: return "medium";
    case En17037Level::high: return "high";
  }
  return "minimum";
}

std::optional<En17037Level> en17037_level_from_name(const std::string& name) {
  for (const En17037Level level : kEn17037Levels)
    if (name == to_string(level)) return level;
  return std::nullopt;
}

En17037Targets en17037_targets(En17037Level level) {
  switch (level) {
    case En17037Level::minimum: return {300.0, 100.0};
    case En17037Level::medium: return {500.0, 300.0};
    case En17037Level::high: return {750.0, 500.0};
  }
  return {300.0, 100.0};
}

double target_fraction(bool top_lit) { return top_lit ? kMinimumTargetFraction : kTargetFraction; }

double target_daylight_factor_percent(double lx, double median_external_diffuse_lx) {
  return 100.0 * lx / median_external_diffuse_lx;
}

namespace {

En17037Criterion criterion(const std::vector<double>& df, const std::vector<bool>& active,
                           std::size_t points, double lx, double median_lx,
                           double required_fraction) {
  En17037Criterion c;
  c.illuminance_lx = lx;
  c.daylight_factor_percent = target_daylight_factor_percent(lx, median_lx);
  c.required_fraction = required_fraction;
  const double at_least = c.daylight_factor_percent * (1.0 - kEn17037AtLimitRelTol);
  std::size_t reaching = 0;
  for (std::size_t i = 0; i < df.size(); ++i)
    if ((active.empty() || active[i]) && df[i] >= at_least) ++reaching;
  c.fraction = points == 0 ? 0.0 : static_cast<double>(reaching) / static_cast<double>(points);
  c.met = points > 0 && c.fraction >= required_fraction * (1.0 - kEn17037AtLimitRelTol);
  return c;
}

}  // namespace

En17037PlaneResult assess_en17037_plane(const std::string& surface,
                                        const std::vector<double>& daylight_factor_percent,
                                        const std::vector<bool>& active, bool top_lit,
                                        double median_external_diffuse_lx) {
  const std::vector<double>& df = daylight_factor_percent;
  En17037PlaneResult out;
  out.surface = surface;
  out.top_lit = top_lit;
  double sum = 0.0, min = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < df.size(); ++i) {
    if (!active.empty() && !active[i]) continue;
    ++out.points;
    sum += df[i];
    min = std::min(min, df[i]);
  }
  if (out.points > 0) {
    out.DF_average_percent = sum / static_cast<double>(out.points);
    out.DF_min_percent = min;
    out.uniformity = out.DF_average_percent > 0.0 ? min / out.DF_average_percent : 0.0;
  }
  for (std::size_t k = 0; k < kEn17037Levels.size(); ++k) {
    En17037LevelResult& r = out.levels[k];
    r.level = kEn17037Levels[k];
    const En17037Targets t = en17037_targets(r.level);
    r.target = criterion(df, active, out.points, t.target_lx, median_external_diffuse_lx,
                         target_fraction(top_lit));
    r.minimum_target = criterion(df, active, out.points, t.minimum_target_lx,
                                 median_external_diffuse_lx, kMinimumTargetFraction);
    r.met = r.target.met && r.minimum_target.met;
    // Each level asks more than the one below: the highest met in a row from minimum.
    if (r.met && (k == 0 || out.achieved)) out.achieved = r.level;
  }
  return out;
}

}  // namespace luxgrid::daylight
