#include "report/colour_rendering.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <set>

#include "util/format.h"

namespace luxgrid::report {

namespace {

std::string upper_without_spaces(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (!std::isspace(static_cast<unsigned char>(c)))
      out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return out;
}

}  // namespace

std::optional<double> parse_colour_rendering(const std::string& text) {
  std::string t = upper_without_spaces(text);
  // The CIE colour rendering groups by their lower Ra bound [CIE29.2].
  static const std::pair<const char*, double> kGroups[] = {{"1A", 90.0}, {"1B", 80.0}, {"2A", 70.0},
                                                           {"2B", 60.0}, {"3", 40.0},  {"4", 20.0}};
  for (const auto& [group, ra] : kGroups) {
    if (t == group) return ra;
  }
  for (const char* prefix : {"RA", "CRI"}) {
    if (t.rfind(prefix, 0) == 0) t = t.substr(std::char_traits<char>::length(prefix));
  }
  for (const char* prefix : {">=", ">", "=", "\xE2\x89\xA5"}) {  // the last is U+2265 (>=)
    if (t.rfind(prefix, 0) == 0) {
      t = t.substr(std::char_traits<char>::length(prefix));
      break;
    }
  }
  if (t.empty()) return std::nullopt;
  for (char& c : t) {
    if (c == ',') c = '.';
  }
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  // A range "80-89" states its lower bound; anything else after the number is not an index.
  if (end == t.c_str() || (*end != '\0' && *end != '-')) return std::nullopt;
  if (!(v >= 0.0 && v <= 100.0)) return std::nullopt;
  return v;
}

std::optional<double> photometry_colour_rendering(const photometry::Photometry& p) {
  std::optional<double> lowest;
  auto take = [&](const std::optional<double>& ra) {
    if (ra) lowest = lowest ? std::min(*lowest, *ra) : *ra;
  };
  for (const auto& set : p.lamp_sets) take(parse_colour_rendering(set.cri));
  for (const auto& [key, value] : p.keywords) {
    const std::string k = upper_without_spaces(key);
    if (k == "_CRI" || k == "CRI" || k == "RA" || k == "_RA") take(parse_colour_rendering(value));
  }
  return lowest;
}

SceneColourRendering scene_colour_rendering(const calc::Scene& scene) {
  std::set<std::string> used;
  for (const auto& l : scene.luminaires) used.insert(l.photometry);
  SceneColourRendering out;
  if (used.empty()) {
    out.source = "no luminaires";
    return out;
  }
  std::optional<double> lowest;
  std::string lowest_entry, unknown;
  for (const auto& key : used) {
    const auto it = scene.photometry.find(key);
    if (it == scene.photometry.end()) continue;
    const auto ra = photometry_colour_rendering(it->second);
    if (!ra) {
      unknown += (unknown.empty() ? "" : ", ") + ("\"" + key + "\"");
      continue;
    }
    if (!lowest || *ra < *lowest) {
      lowest = ra;
      lowest_entry = key;
    }
  }
  if (!unknown.empty()) {
    out.source = "unknown: photometry " + unknown + " states no colour rendering index";
    return out;
  }
  out.Ra = lowest;
  out.source = "photometry \"" + lowest_entry + "\": Ra " + format_double("%g", *lowest);
  return out;
}

}  // namespace luxgrid::report
