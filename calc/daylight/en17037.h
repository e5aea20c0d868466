#pragma once
// EN 17037 daylight provision by the daylight-factor method [EN17037, Annex A]:
// the three levels of recommendation, their target illuminances, the daylight factors they ask
// for at a site, and the fraction of a reference plane that reaches each (docs/daylight.md).
// The site's median external diffuse illuminance is the user's (the standard tabulates it per
// capital in its Annex; luxgrid ships no such table).
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace luxgrid::daylight {

enum class En17037Level { minimum, medium, high };
inline constexpr std::array<En17037Level, 3> kEn17037Levels = {
    En17037Level::minimum, En17037Level::medium, En17037Level::high};
const char* to_string(En17037Level level);
// "minimum", "medium", "high"; none for anything else.
std::optional<En17037Level> en17037_level_from_name(const std::string& name);

// The reference plane lies 0.85 m above the floor with a band of 0.5 m along the walls left
// out [EN17037, Annex A]: a project's reference plane is a workplane surface at that height
// and border (project/project_daylight warns about one that is not).
inline constexpr double kEn17037PlaneHeight_m = 0.85;
inline constexpr double kEn17037PlaneBorder_m = 0.5;

// The level's target illuminance E_T, to be reached over half of the reference plane, and its
// minimum target illuminance E_TM, over 95 % of it, each for half of the daylight hours
// [EN17037, Annex A]: 300 / 100 lx (minimum), 500 / 300 lx (medium), 750 / 500 lx (high).
struct En17037Targets {
  double target_lx = 0.0;          // E_T
  double minimum_target_lx = 0.0;  // E_TM
};
En17037Targets en17037_targets(En17037Level level);

// The fraction of the reference plane each target must reach: E_T over 50 %, E_TM over 95 %; a
// top-lit space (all its openings in the roof) asks 95 % for both [EN17037, Annex A].
inline constexpr double kTargetFraction = 0.5;
inline constexpr double kMinimumTargetFraction = 0.95;
double target_fraction(bool top_lit);

// The daylight factor (percent) that gives illuminance `lx` at the median external diffuse
// illuminance of the site: D = 100 E / E_v,d,med.
double target_daylight_factor_percent(double lx, double median_external_diffuse_lx);

// One reference plane the project asks to assess.
struct En17037PlaneRef {
  std::string surface;  // a workplane surface of the project
  bool top_lit = false;
};

// What the project asks (daylight.en17037, docs/project-format.md).
struct En17037Request {
  double median_external_diffuse_lx = 0.0;  // E_v,d,med of the site
  En17037Level level = En17037Level::minimum;
  std::vector<En17037PlaneRef> planes;
};

// One target on one plane: the daylight factor it asks for, the fraction of the plane it asks
// that fraction to reach, the fraction that does.
struct En17037Criterion {
  double illuminance_lx = 0.0;
  double daylight_factor_percent = 0.0;
  double required_fraction = 0.0;
  double fraction = 0.0;  // of the plane's active points with DF >= daylight_factor_percent
  bool met = false;
};

struct En17037LevelResult {
  En17037Level level = En17037Level::minimum;
  En17037Criterion target, minimum_target;  // E_T, E_TM
  bool met = false;                         // both
};

struct En17037PlaneResult {
  std::string surface;
  bool top_lit = false;
  std::size_t points = 0;  // active points: each stands for an equal part of the plane
  double DF_average_percent = 0.0, DF_min_percent = 0.0;
  double uniformity = 0.0;  // DF_min / DF_average (0 when the average is 0)
  std::array<En17037LevelResult, 3> levels;
  std::optional<En17037Level> achieved;  // the highest level met; none below minimum
};

struct En17037Assessment {
  double median_external_diffuse_lx = 0.0;
  En17037Level asked = En17037Level::minimum;
  std::vector<En17037PlaneResult> planes;
};

// A point exactly at a target reaches it, and a fraction exactly at the required one meets it;
// a relative slack of 1e-9 keeps an average or a fraction that lands one ulp short of the limit
// met (as report/requirement_checks' kAtLimitRelTol).
inline constexpr double kEn17037AtLimitRelTol = 1e-9;

// The plane's result from its daylight factors (percent) and the points that count (`active`:
// empty for all). Grid points at cell centres of a regular grid stand for equal areas, so the
// fraction of the plane is the fraction of its active points.
En17037PlaneResult assess_en17037_plane(const std::string& surface,
                                        const std::vector<double>& daylight_factor_percent,
                                        const std::vector<bool>& active, bool top_lit,
                                        double median_external_diffuse_lx);

}  // namespace luxgrid::daylight
