#pragma once
// Comparing two calculations point by point: `luxgrid diff A B`, the regression tests, and the
// accuracy-versus-time table of `luxgrid cost` all use the same measure of difference.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calc/statistics.h"

namespace luxgrid::report {

// A point's relative difference is |a - b| / max(|b|, kRelativeFloor * max|b| over the surface).
// Without the floor a point in near darkness (1e-6 lx against 2e-6 lx) would count as a 50 %
// error and drown the differences that matter; 1 % of the surface's brightest point keeps the
// measure relative where people read the plot and absolute in the dark corners.
inline constexpr double kRelativeFloor = 0.01;

struct PointDifference {
  double max_rel = 0.0;   // largest relative difference, 0.02 = 2 %
  double mean_rel = 0.0;  // mean relative difference over the points
  size_t worst_index = 0;
};

// `a` against the reference `b`. Both must have the same length (the caller checks and names
// the surface).
PointDifference point_difference(const std::vector<double>& a, const std::vector<double>& b);

// The promise's measure (docs/accuracy.md, "The plan's own estimate"): |a - b| / b at the points
// where b is brighter than kRelativeFloor of the surface's largest b. The darker points are
// promised nothing and count neither way (point_difference's floor would still charge them).
struct PromiseError {
  double max_rel = 0.0;  // largest relative error over the bright points, 0.01 = 1 %
  size_t worst_index = 0;
  size_t bright_points = 0;  // points brighter than the floor
};
PromiseError promise_error(const std::vector<double>& a, const std::vector<double>& b);

struct SurfaceDiff {
  std::string name;
  size_t points = 0;  // the points both files calculated (active in both)
  PointDifference diff;
  calc::Statistics a, b;
  PromiseError promise;  // worst_index counts the surface's points in the file, active or not
  double promise_a_lx = 0.0, promise_b_lx = 0.0;         // E of A and B at promise's worst point
  std::optional<std::array<double, 3>> promise_point_m;  // where it is, when A holds "points"
};

struct ResultsDiff {
  std::string label_a, label_b;
  std::vector<SurfaceDiff> surfaces;
  double max_rel = 0.0;          // over all surfaces
  double promise_max_rel = 0.0;  // the promise's measure, over all surfaces
};

// Compares two results.json documents surface by surface (matched by name). Throws InputError
// naming the file and the surface when the two do not describe the same surfaces and points (the
// same count, and where both hold "points", the same positions within 1e-6 m). Only "format"
// and each surface's "name" and "E" are required: a reference kept for a test may be a results
// file reduced to its surfaces' names, points, "active" flags and E (tests/rooms/README.md).
ResultsDiff diff_results(const nlohmann::json& a, const std::string& label_a,
                         const nlohmann::json& b, const std::string& label_b);

// Reads a results.json, or the results.json inside an output folder. InputError if unreadable.
nlohmann::json read_results_file(const std::filesystem::path& path);

// What accuracy costs on one project (`luxgrid cost`): the same scene at each quality, with its
// wall time and each surface's statistics and point difference to the reference run.
struct CostSurface {
  std::string name;
  calc::Statistics stats;
  PointDifference to_reference;
  double estimate = 0.0;  // the plan's own estimate of its error (calc::SurfaceEstimate::total)
};
struct CostLevel {
  std::string quality;
  double time_s = 0.0;  // wall time of the calculation (plan, direct, indirect)
  std::string direct, indirect, visibility;  // what this level simulated (the plan in words)
  std::string promise;                       // what the level promises (report::promise_text)
  double promised_error = 0.0;               // as a number; 0: no number promised
  std::vector<std::string> warnings;         // the plan's: estimates above the promise
  std::vector<CostSurface> surfaces;
};
struct CostTable {
  std::vector<CostLevel> levels;  // draft, standard, high, reference; the last is the reference
};

// One block per surface: quality, time, Eavg, Emin, U0, max and mean difference to reference,
// the plan's own estimate beside them and the promise; then the plan of each level.
std::string format_cost_table(const CostTable& t);

// The table `luxgrid diff` prints: one line per surface, the statistics side by side.
std::string format_diff(const ResultsDiff& d);

// The table `luxgrid diff --promise` prints: per surface the promise's measure, its point and E.
std::string format_promise_diff(const ResultsDiff& d);

}  // namespace luxgrid::report
