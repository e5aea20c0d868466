#include "report/results_json.h"
#include "report/json_fields.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string_view>

#include "report/chunked_text.h"
#include "report/json_fields.h"
#include "report/number_text_memo.h"
#include "report/piece_buffer.h"
#include "report/plan_json.h"
#include "report/plan_text.h"

namespace luxgrid::report {

namespace {
// The per-point arrays of a surface, in the order results_outline_json leaves placeholders.
enum class PointArray { points, normals, active, E, E_direct, E_indirect };
constexpr std::array<std::pair<PointArray, const char*>, 6> kPointArrays = {
    {{PointArray::points, "points"},
     {PointArray::normals, "normals"},
     {PointArray::active, "active"},
     {PointArray::E, "E"},
     {PointArray::E_direct, "E_direct"},
     {PointArray::E_indirect, "E_indirect"}}};
// A placeholder's text starts with a control character, which dump() writes escaped: the
// escaped form after a key at the start of a line cannot come from any string of the input.
constexpr std::string_view kPlaceholderTag = "\\u0001points ";

// Per observer its views: line of sight, UGR (null when no luminaire counts), background
// luminance (cd/m2), the indirect illuminance it comes from, and each counted luminaire's term.
nlohmann::json observers_json(const std::vector<calc::glare::ObserverResult>& observers) {
  using nlohmann::json;
  json out = json::array();
  for (const auto& o : observers) {
    json views = json::array();
    for (const auto& v : o.views) {
      json terms = json::array();
      for (const auto& t : v.terms) {
        terms.push_back({{"luminaire", t.luminaire},
                         {"L", t.term.L_cd_m2},
                         {"omega", t.term.omega_sr},
                         {"p", t.term.p}});
      }
      views.push_back({{"direction", vec3_json(v.direction)},
                       {"UGR", v.UGR ? json(*v.UGR) : json(nullptr)},
                       {"Lb", v.Lb_cd_m2},
                       {"E_indirect", v.E_indirect_lx},
                       {"terms", std::move(terms)}});
    }
    out.push_back({{"at", vec3_json(o.at)}, {"views", std::move(views)}});
  }
  return out;
}

// `index`: the surface's place in the results; with `arrays` false the per-point arrays are
// placeholders naming it (character 1, "points", the surface and the array: "\\u0001points 3 4"
// once dumped).
nlohmann::json surface_json(const calc::SurfaceResult& r, size_t index, bool arrays) {
  using nlohmann::json;
  const auto& g = r.grid;
  json s;
  s["name"] = g.name;
  s["kind"] = geometry::to_string(g.kind);
  s["size"] = json::array({g.nu, g.nv});
  if (g.kind == geometry::SurfaceGrid::Kind::grid) {
    s["spacing"] = json::array({g.spacing_u, g.spacing_v});
  }
  // What geometry did to the grid: the quantity its numbers are, and the points it kept in the
  // nu x nv layout but left out of the calculation and the statistics (their E is 0).
  s["quantity"] = geometry::to_string(g.quantity);
  s["points_outside"] = g.points_outside;
  s["points_in_obstacles"] = g.points_in_obstacles;
  // Only a grid over a face with openings has points in them: the key is there when it counts.
  if (g.points_in_openings > 0) s["points_in_openings"] = g.points_in_openings;
  if (arrays) {
    json points = json::array(), normals = json::array();
    for (size_t i = 0; i < g.points.size(); ++i) {
      points.push_back(vec3_json(g.points[i]));
      normals.push_back(vec3_json(g.normals[i]));
    }
    s["points"] = std::move(points);
    s["normals"] = std::move(normals);
    // false for the points left out above: their E is 0 and the statistics skip them.
    json active = json::array();
    for (size_t i = 0; i < g.points.size(); ++i) active.push_back(g.active.empty() || g.active[i]);
    s["active"] = std::move(active);
    s["E"] = r.E;
    s["E_direct"] = r.E_direct;
    s["E_indirect"] = r.E_indirect;
  } else {
    for (const auto& [array, key] : kPointArrays) {
      s[key] =
          "\x01points " + std::to_string(index) + " " + std::to_string(static_cast<int>(array));
    }
  }
  s["stats"] = {{"Emin", r.stats.Emin},
                {"Eavg", r.stats.Eavg},
                {"Emax", r.stats.Emax},
                {"U0", r.stats.U0},
                {"Ud", r.stats.Ud}};
  // The daylight scene's components, percent of E_h (calc/results.h; docs/daylight.md).
  if (!r.DF.empty()) s["DF"] = r.DF, s["SC"] = r.SC, s["ERC"] = r.ERC, s["IRC"] = r.IRC;
  // Direct sun (lx): no part of DF; E holds it.
  if (!r.E_sun_direct.empty())
    s["E_sun_direct"] = r.E_sun_direct, s["E_sun_reflected"] = r.E_sun_reflected;
  if (g.kind == geometry::SurfaceGrid::Kind::observers) {
    s["UGR_max"] = r.UGR_max ? json(*r.UGR_max) : json(nullptr);
    s["observers"] = observers_json(r.observers);
  }
  return s;
}

nlohmann::json document(const calc::Results& results, const std::vector<std::string>& warnings,
                        const ResultsOrigin& origin, bool arrays) {
  using nlohmann::json;
  json j;
  j["format"] = kResultsFormat;
  j["luxgrid_version"] = origin.version;
  j["project"] = results.project;
  j["project_sha256"] = origin.project_sha256;
  j["quality"] = calc::to_string(results.quality);
  // "emergency": EN 1838's scene, direct light from the emergency luminaires only
  // (calc/emergency_scene.h).
  j["scene"] = calc::to_string(results.scene);
  j["maintenance_factor"] = results.maintenance_factor;
  // Every E, E_direct and E_indirect below: E = E_direct + E_indirect, all times the factor.
  j["values"] = "maintained";
  // The plan: every decision as a value, with a short summary in words (report/plan_json.h).
  j["plan"] = plan_to_json(results.plan);
  // Warnings: the scene's and the outputs' (given), then the plan's (an estimate above the
  // promise).
  json all_warnings = warnings;
  for (const auto& w : plan_warnings(results.plan)) all_warnings.push_back(w);
  j["warnings"] = std::move(all_warnings);
  j["surfaces"] = json::array();
  for (size_t k = 0; k < results.surfaces.size(); ++k)
    j["surfaces"].push_back(surface_json(results.surfaces[k], k, arrays));
  return j;
}

// Writes through a buffer of its own: a million small writes to an ostream cost more than the
// numbers' formatting.
class Buffered {
 public:
  explicit Buffered(std::ostream& out) : out_(out) { buf_.reserve(kFlushAt + 256); }
  ~Buffered() { flush(); }
  Buffered(const Buffered&) = delete;
  Buffered& operator=(const Buffered&) = delete;
  void text(std::string_view t) {
    buf_.append(t);
    if (buf_.size() >= kFlushAt) flush();
  }
  void indent(size_t n) { buf_.append(n, ' '); }
  void flush() {
    out_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
    buf_.clear();
  }

 private:
  static constexpr size_t kFlushAt = 1 << 20;
  std::ostream& out_;
  std::string buf_;
};

// A number exactly as nlohmann::json's dump writes it: a short text that reads back to the same
// double, "null" for a non-finite value. Its Grisu2 digits are not always std::to_chars's
// shortest ones (about one random double in 1500 ends differently), so they are kept.
struct JsonNumber {
  char* operator()(double v, char* first) const {
    if (!std::isfinite(v)) return std::copy_n("null", 4, first);
    return nlohmann::detail::to_chars(first, first + NumberTextMemo<JsonNumber>::kMaxChars, v);
  }
};

// Elements a chunk: a few tens of kB of text, formatted in parallel (report/chunked_text.h),
// small for the same reason as the CSV's rows (report/csv.cpp).
constexpr size_t kElementsPerChunk = 1024;

// A line of an array below depth is at most depth + kLineChars long: the indent, a number of up
// to 24 characters ("-1.2345678901234567e-308") and ",\n".
constexpr size_t kLineChars = 28;

// One array in dump(1)'s layout at `depth` (the indent of the line holding its key): "[]" when
// empty, else one element a line at depth + 1 and the closing bracket at depth. `element(i,
// depth, pieces)` puts element i's text; the elements are made in parallel chunks.
template <typename Element>
void write_array(Buffered& out, size_t count, size_t depth, size_t lines_each,
                 const Element& element, std::string* copy = nullptr) {
  if (count == 0) {
    if (copy) *copy = "[]";
    return out.text("[]");
  }
  if (copy) {
    // Reserved once, as the chunks are.
    copy->reserve(count * lines_each * (depth + kLineChars) + depth + 4);
    *copy = "[\n";
  }
  out.text("[\n");
  write_chunked(
      count, kElementsPerChunk,
      [&](size_t begin, size_t end, std::string& text) {
        // Reserved once, so the chunk's text is not copied as it grows.
        text.reserve((end - begin) * lines_each * (depth + kLineChars));
        PieceBuffer pieces(text);
        for (size_t i = begin; i < end; ++i) {
          pieces.spaces(depth + 1);
          element(i, depth + 1, pieces);
          pieces.put(i + 1 < count ? ",\n" : "\n");
        }
      },
      [&](std::string_view text) {
        out.text(text);
        if (copy) copy->append(text);
      });
  out.indent(depth);
  out.text("]");
  if (copy) copy->append(depth, ' ').append("]");
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

// Without reflected light E_direct is E bit for bit: E_direct's text is E's, kept while E is
// written (a few bytes a point, for one array) instead of formatted a second time.
struct KeptText {
  const calc::SurfaceResult* surface = nullptr;
  size_t depth = 0;
  std::string text;
};

void write_point_array(Buffered& out, const calc::SurfaceResult& r, PointArray array, size_t depth,
                       KeptText& kept) {
  const auto& g = r.grid;
  // One memo per thread: the chunks of one array (and the next array) share its repeats.
  auto number = [](double v, PieceBuffer& text) {
    static thread_local NumberTextMemo<JsonNumber> memo;
    text.put(memo.text(v));
  };
  auto vectors = [&](const std::vector<Vec3>& v) {
    write_array(out, v.size(), depth, 5, [&](size_t i, size_t d, PieceBuffer& text) {
      // [x, y, z] one a line, as dump(1) writes a three-element array at depth d.
      text.put("[\n");
      for (glm::length_t c = 0; c < 3; ++c) {
        text.spaces(d + 1);
        number(v[i][c], text);
        text.put(c < 2 ? ",\n" : "\n");
      }
      text.spaces(d);
      text.put(']');
    });
  };
  auto numbers = [&](const std::vector<double>& v, std::string* copy = nullptr) {
    write_array(
        out, v.size(), depth, 1, [&](size_t i, size_t, PieceBuffer& text) { number(v[i], text); },
        copy);
  };
  switch (array) {
    case PointArray::points: return vectors(g.points);
    case PointArray::normals: return vectors(g.normals);
    case PointArray::active:
      return write_array(out, g.points.size(), depth, 1, [&](size_t i, size_t, PieceBuffer& text) {
        text.put(g.active.empty() || g.active[i] ? "true" : "false");
      });
    case PointArray::E:
      if (!same_bits(r.E_direct, r.E)) return numbers(r.E);
      kept.surface = &r, kept.depth = depth;
      return numbers(r.E, &kept.text);
    case PointArray::E_direct:
      if (kept.surface == &r && kept.depth == depth && same_bits(r.E_direct, r.E)) {
        out.text(kept.text);
        kept = KeptText{};
        return;
      }
      return numbers(r.E_direct);
    case PointArray::E_indirect: return numbers(r.E_indirect);
  }
}
}  // namespace

nlohmann::json results_to_json(const calc::Results& results,
                               const std::vector<std::string>& warnings,
                               const ResultsOrigin& origin) {
  return document(results, warnings, origin, true);
}

nlohmann::json results_outline_json(const calc::Results& results,
                                    const std::vector<std::string>& warnings,
                                    const ResultsOrigin& origin) {
  return document(results, warnings, origin, false);
}

void write_results_json(std::ostream& stream, const nlohmann::json& outline,
                        const calc::Results& results) {
  const std::string text = outline.dump(1);
  Buffered out(stream);
  KeptText kept;
  size_t from = 0;
  // Each placeholder is the value of a key at the start of a line: `\n<indent>"key": "\u0001points
  // K A"`.
  const std::string tag = "\"" + std::string(kPlaceholderTag);
  for (size_t at = text.find(tag); at != std::string::npos; at = text.find(tag, at + 1)) {
    const size_t line = text.rfind('\n', at);
    if (line == std::string::npos) continue;
    const size_t depth = text.find_first_not_of(' ', line + 1) - (line + 1);
    if (text[line + 1 + depth] != '"' || text.compare(at - 3, 3, "\": ") != 0) continue;
    const size_t close = text.find('"', at + 1);
    size_t surface = 0;
    int array = 0;
    if (std::sscanf(text.c_str() + at + tag.size(), "%zu %d", &surface, &array) != 2 ||
        surface >= results.surfaces.size() || array < 0 ||
        array >= static_cast<int>(kPointArrays.size()))
      continue;
    out.text(std::string_view(text).substr(from, at - from));
    write_point_array(out, results.surfaces[surface], static_cast<PointArray>(array), depth, kept);
    from = close + 1;
  }
  out.text(std::string_view(text).substr(from));
  out.text("\n");
}

nlohmann::json timing_to_json(const calc::Results& results) {
  nlohmann::json j;
  j["timing_s"] = nlohmann::json::object();
  for (const auto& [phase, seconds] : results.timing_s) j["timing_s"][phase] = seconds;
  return j;
}

}  // namespace luxgrid::report
