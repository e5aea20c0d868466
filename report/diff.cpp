#include "report/diff.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "project/json_reader.h"
#include "project/safe_json.h"
#include "report/results_json.h"
#include "util/error.h"

namespace luxgrid::report {

namespace fs = std::filesystem;

namespace {

// kRelativeFloor of the reference's largest value: the floor of point_difference's measure and
// the brightness promise_error's points must exceed.
double relative_floor(const std::vector<double>& b) {
  double bmax = 0.0;
  for (double v : b) bmax = std::max(bmax, std::abs(v));
  return kRelativeFloor * bmax;
}

}  // namespace

PointDifference point_difference(const std::vector<double>& a, const std::vector<double>& b) {
  PointDifference d;
  if (a.empty() || a.size() != b.size()) return d;
  const double floor = relative_floor(b);
  double sum = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    const double diff = std::abs(a[i] - b[i]);
    const double denom = std::max(std::abs(b[i]), floor);
    const double rel = diff == 0.0 ? 0.0 : (denom > 0.0 ? diff / denom : INFINITY);
    sum += rel;
    if (rel > d.max_rel) {
      d.max_rel = rel;
      d.worst_index = i;
    }
  }
  d.mean_rel = sum / static_cast<double>(a.size());
  return d;
}

PromiseError promise_error(const std::vector<double>& a, const std::vector<double>& b) {
  PromiseError e;
  if (a.empty() || a.size() != b.size()) return e;
  const double floor = relative_floor(b);
  for (size_t i = 0; i < a.size(); ++i) {
    if (!(std::abs(b[i]) > floor)) continue;
    ++e.bright_points;
    const double rel = std::abs(a[i] - b[i]) / std::abs(b[i]);
    if (rel > e.max_rel || e.bright_points == 1) {
      e.max_rel = rel;
      e.worst_index = i;
    }
  }
  return e;
}

namespace {

// The array of numbers s[key], s being /surfaces/<index> of the file `label`.
std::vector<double> numbers_at(const nlohmann::json& s, const char* key, const std::string& label,
                               size_t index) {
  const std::string where = "/surfaces/" + std::to_string(index) + "/" + key;
  const auto it = s.find(key);
  if (it == s.end() || !it->is_array())
    throw InputError(SourceLocation{label, 0, 0, where}, "expected an array of numbers");
  std::vector<double> out;
  out.reserve(it->size());
  for (size_t i = 0; i < it->size(); ++i) {
    const auto& v = (*it)[i];
    if (!v.is_number()) {
      throw InputError(SourceLocation{label, 0, 0, where + "/" + std::to_string(i)},
                       "expected a number, got " + project::json_type_name(v));
    }
    out.push_back(v.get<double>());
  }
  return out;
}

// s["points"] as positions in metres; empty when the surface holds none (a reduced reference may
// leave them out).
std::vector<std::array<double, 3>> points_at(const nlohmann::json& s, const std::string& label,
                                             size_t index) {
  std::vector<std::array<double, 3>> out;
  const auto it = s.find("points");
  if (it == s.end()) return out;
  const std::string where = "/surfaces/" + std::to_string(index) + "/points";
  if (!it->is_array()) throw InputError(SourceLocation{label, 0, 0, where}, "expected an array");
  out.reserve(it->size());
  for (size_t i = 0; i < it->size(); ++i) {
    const auto& p = (*it)[i];
    if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() ||
        !p[2].is_number()) {
      throw InputError(SourceLocation{label, 0, 0, where + "/" + std::to_string(i)},
                       "expected [x, y, z] in metres");
    }
    out.push_back({p[0].get<double>(), p[1].get<double>(), p[2].get<double>()});
  }
  return out;
}

// Two results compared point by point must have calculated the same points: a grid moved by a
// changed project would otherwise pass as a difference in light. 1e-6 m is far below any grid's
// spacing and far above the printing of a double.
void check_same_points(const std::string& name, const std::vector<std::array<double, 3>>& pa,
                       const std::string& label_a, const std::vector<std::array<double, 3>>& pb,
                       const std::string& label_b) {
  constexpr double kSamePointM = 1e-6;
  if (pa.empty() || pb.empty()) return;
  if (pa.size() != pb.size()) {
    throw InputError("surface \"" + name + "\": " + label_a + " has " + std::to_string(pa.size()) +
                     " points, " + label_b + " has " + std::to_string(pb.size()));
  }
  for (size_t i = 0; i < pa.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      if (std::abs(pa[i][k] - pb[i][k]) > kSamePointM) {
        char at[160];
        std::snprintf(at, sizeof at, "point %zu is at (%.6g, %.6g, %.6g) m in %s", i, pa[i][0],
                      pa[i][1], pa[i][2], label_a.c_str());
        char other[160];
        std::snprintf(other, sizeof other, " and at (%.6g, %.6g, %.6g) m in %s", pb[i][0], pb[i][1],
                      pb[i][2], label_b.c_str());
        throw InputError("surface \"" + name + "\": " + at + other);
      }
    }
  }
}

// The points both files calculated: results.json marks the points a grid left out (outside an
// L-shaped workplane, inside an obstacle) "active": false; their E is 0 in both and would only
// dilute the mean difference. Files without the array (format 1) count every point. Returns the
// kept points' indices in the file.
std::vector<size_t> keep_active(const nlohmann::json& sa, const nlohmann::json& sb,
                                std::vector<double>& ea, std::vector<double>& eb) {
  auto flags = [&](const nlohmann::json& s) {
    std::vector<bool> out(ea.size(), true);
    const auto it = s.find("active");
    if (it == s.end() || !it->is_array() || it->size() != ea.size()) return out;
    for (size_t i = 0; i < ea.size(); ++i) out[i] = !(*it)[i].is_boolean() || (*it)[i].get<bool>();
    return out;
  };
  const auto fa = flags(sa), fb = flags(sb);
  std::vector<size_t> kept;
  for (size_t i = 0; i < ea.size(); ++i) {
    if (!(fa[i] && fb[i])) continue;
    ea[kept.size()] = ea[i];
    eb[kept.size()] = eb[i];
    kept.push_back(i);
  }
  ea.resize(kept.size());
  eb.resize(kept.size());
  return kept;
}

calc::Statistics stats_of(const nlohmann::json& s) {
  calc::Statistics st;
  const auto it = s.find("stats");
  if (it == s.end() || !it->is_object()) return st;
  auto get = [&](const char* k) {
    return it->contains(k) && (*it)[k].is_number() ? (*it)[k].get<double>() : 0.0;
  };
  st.Emin = get("Emin");
  st.Eavg = get("Eavg");
  st.Emax = get("Emax");
  st.U0 = get("U0");
  st.Ud = get("Ud");
  return st;
}

const nlohmann::json& surfaces_of(const nlohmann::json& doc, const std::string& label) {
  if (!doc.is_object() || !doc.contains("format") ||
      (doc["format"] != kResultsFormat && doc["format"] != kResultsFormatV1)) {
    throw InputError(SourceLocation{label}, "not a luxgrid results file (expected \"format\": \"" +
                                                std::string(kResultsFormat) + "\")");
  }
  const auto it = doc.find("surfaces");
  if (it == doc.end() || !it->is_array())
    throw InputError(SourceLocation{label, 0, 0, "/surfaces"}, "expected an array");
  for (size_t i = 0; i < it->size(); ++i) {
    if (!(*it)[i].is_object() || !(*it)[i].contains("name") || !(*it)[i]["name"].is_string()) {
      throw InputError(SourceLocation{label, 0, 0, "/surfaces/" + std::to_string(i) + "/name"},
                       "expected a string");
    }
  }
  return *it;
}

}  // namespace

ResultsDiff diff_results(const nlohmann::json& a, const std::string& label_a,
                         const nlohmann::json& b, const std::string& label_b) {
  const auto& sa = surfaces_of(a, label_a);
  const auto& sb = surfaces_of(b, label_b);
  auto find = [](const nlohmann::json& list, const std::string& name) -> const nlohmann::json* {
    for (const auto& s : list) {
      if (s["name"] == name) return &s;
    }
    return nullptr;
  };
  // Every surface must be in both: a missing one is named, from whichever side lacks it.
  for (const auto& s : sa) {
    const std::string name = s["name"];
    if (!find(sb, name))
      throw InputError(SourceLocation{label_b},
                       "surface \"" + name + "\" of " + label_a + " is missing");
  }
  for (const auto& s : sb) {
    const std::string name = s["name"];
    if (!find(sa, name))
      throw InputError(SourceLocation{label_a},
                       "surface \"" + name + "\" of " + label_b + " is missing");
  }
  ResultsDiff out{label_a, label_b, {}, 0.0};
  for (size_t i = 0; i < sa.size(); ++i) {
    const std::string name = sa[i]["name"];
    const nlohmann::json& other = *find(sb, name);
    size_t j = 0;
    while (sb[j]["name"] != name) ++j;
    auto ea = numbers_at(sa[i], "E", label_a, i);
    auto eb = numbers_at(other, "E", label_b, j);
    if (ea.size() != eb.size()) {
      throw InputError("surface \"" + name + "\": " + label_a + " has " +
                       std::to_string(ea.size()) + " points, " + label_b + " has " +
                       std::to_string(eb.size()));
    }
    const auto pa = points_at(sa[i], label_a, i);
    check_same_points(name, pa, label_a, points_at(other, label_b, j), label_b);
    const auto kept = keep_active(sa[i], other, ea, eb);
    SurfaceDiff d;
    d.name = name;
    d.points = ea.size();
    d.diff = point_difference(ea, eb);
    d.a = stats_of(sa[i]);
    d.b = stats_of(other);
    d.promise = promise_error(ea, eb);
    if (d.promise.bright_points > 0) {
      d.promise_a_lx = ea[d.promise.worst_index];
      d.promise_b_lx = eb[d.promise.worst_index];
      d.promise.worst_index = kept[d.promise.worst_index];
      if (d.promise.worst_index < pa.size()) d.promise_point_m = pa[d.promise.worst_index];
    }
    out.max_rel = std::max(out.max_rel, d.diff.max_rel);
    out.promise_max_rel = std::max(out.promise_max_rel, d.promise.max_rel);
    out.surfaces.push_back(std::move(d));
  }
  return out;
}

nlohmann::json read_results_file(const fs::path& path) {
  fs::path file = path;
  if (fs::is_directory(file)) file /= "results.json";
  return project::read_json_file(file, project::kMaxResultsFileBytes, "results file");
}

std::string format_diff(const ResultsDiff& d) {
  std::string out;
  char line[512];
  std::snprintf(line, sizeof line, "A = %s\nB = %s (reference)\n", d.label_a.c_str(),
                d.label_b.c_str());
  out += line;
  std::snprintf(line, sizeof line, "%-20s %6s %9s %9s  %19s  %19s  %19s  %13s\n", "surface",
                "points", "max diff", "mean diff", "Emin A / B lx", "Eavg A / B lx",
                "Emax A / B lx", "U0 A / B");
  out += line;
  for (const auto& s : d.surfaces) {
    std::snprintf(
        line, sizeof line,
        "%-20s %6zu %8.3f%% %8.3f%%  %9.2f %9.2f  %9.2f %9.2f  %9.2f %9.2f  %6.3f %6.3f\n",
        s.name.c_str(), s.points, 100.0 * s.diff.max_rel, 100.0 * s.diff.mean_rel, s.a.Emin,
        s.b.Emin, s.a.Eavg, s.b.Eavg, s.a.Emax, s.b.Emax, s.a.U0, s.b.U0);
    out += line;
  }
  std::snprintf(line, sizeof line, "largest relative difference: %.3f %%\n", 100.0 * d.max_rel);
  out += line;
  return out;
}

std::string format_promise_diff(const ResultsDiff& d) {
  std::string out;
  char line[512];
  std::snprintf(line, sizeof line,
                "A = %s\nB = %s (reference)\nerror: |A - B| / B at the points where B is brighter "
                "than %g %% of its surface's largest B\n",
                d.label_a.c_str(), d.label_b.c_str(), 100.0 * kRelativeFloor);
  out += line;
  std::snprintf(line, sizeof line, "%-20s %6s %6s %9s  %6s  %-26s  %19s\n", "surface", "points",
                "bright", "max error", "index", "at x, y, z m", "E A / B lx");
  out += line;
  for (const auto& s : d.surfaces) {
    char at[64] = "-";
    if (s.promise_point_m) {
      std::snprintf(at, sizeof at, "%.3f, %.3f, %.3f", (*s.promise_point_m)[0],
                    (*s.promise_point_m)[1], (*s.promise_point_m)[2]);
    }
    std::snprintf(line, sizeof line, "%-20s %6zu %6zu %8.3f%%  %6zu  %-26s  %9.2f %9.2f\n",
                  s.name.c_str(), s.points, s.promise.bright_points, 100.0 * s.promise.max_rel,
                  s.promise.worst_index, at, s.promise_a_lx, s.promise_b_lx);
    out += line;
  }
  std::snprintf(line, sizeof line, "largest error: %.3f %%\n", 100.0 * d.promise_max_rel);
  out += line;
  return out;
}

std::string format_cost_table(const CostTable& t) {
  std::string out;
  char line[512];
  if (t.levels.empty()) return out;
  for (size_t si = 0; si < t.levels.front().surfaces.size(); ++si) {
    std::snprintf(line, sizeof line, "%s\n  %-10s %9s %10s %10s %7s %10s %10s %10s %9s\n",
                  t.levels.front().surfaces[si].name.c_str(), "quality", "time s", "Eavg lx",
                  "Emin lx", "U0", "max diff", "estimate", "mean diff", "promise");
    out += line;
    for (const auto& l : t.levels) {
      if (si >= l.surfaces.size()) continue;
      const auto& s = l.surfaces[si];
      char promise[32] = "-";
      if (l.promised_error > 0.0)
        std::snprintf(promise, sizeof promise, "%.3g%%", 100.0 * l.promised_error);
      // The measured difference and the plan's estimate side by side; "!" marks an estimate above
      // the promise (the run warned about it).
      const bool over = l.promised_error > 0.0 && s.estimate > l.promised_error;
      std::snprintf(line, sizeof line,
                    "  %-10s %9.3f %10.2f %10.2f %7.3f %9.3f%% %9.3f%%%s%9.3f%% %9s\n",
                    l.quality.c_str(), l.time_s, s.stats.Eavg, s.stats.Emin, s.stats.U0,
                    100.0 * s.to_reference.max_rel, 100.0 * s.estimate, over ? "!" : " ",
                    100.0 * s.to_reference.mean_rel, promise);
      out += line;
    }
  }
  out +=
      "max diff: the largest difference to reference relative to max(E, 1 % of the surface's "
      "maximum); "
      "estimate: the plan's own estimate of it (\"!\": above the promise)\n";
  out += "what each level promises\n";
  for (const auto& l : t.levels) out += "  " + l.quality + ": " + l.promise + "\n";
  out += "what each level simulated\n";
  for (const auto& l : t.levels) {
    out += "  " + l.quality + ": direct: " + l.direct + "; indirect: " + l.indirect +
           "; visibility: " + l.visibility + "\n";
  }
  return out;
}

}  // namespace luxgrid::report
