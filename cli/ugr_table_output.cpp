#include "cli/ugr_table_output.h"

#include <cstdio>

namespace luxgrid::cli {

namespace {
using calc::glare::kTableReflectances;
using calc::glare::kTableRooms;

std::string cell(const std::optional<double>& v, double add) {
  char buf[16];
  if (!v) return "    -";
  std::snprintf(buf, sizeof buf, "%5.1f", *v + add);
  return buf;
}

nlohmann::json values(const std::array<std::optional<double>, 5>& row, double add) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& v : row) a.push_back(v ? nlohmann::json(*v + add) : nlohmann::json(nullptr));
  return a;
}
}  // namespace

std::string ugr_table_text(const calc::glare::UgrTable& t) {
  std::string out;
  char line[256];
  std::snprintf(
      line, sizeof line,
      "UGR table (CIE 190 tabular method, CIE 117 formula; S = %.2fH, observer at eye level "
      "mid-wall)\n"
      "  values for the lamp flux F = %.1f lm: the 1000 lm table %+.1f (8 log10(F / 1000))\n",
      calc::glare::kTableSpacingOverH, t.lamp_flux_lm, t.correction);
  out += line;
  const char* names[3] = {"ceiling", "walls  ", "floor  "};
  for (int k = 0; k < 3; ++k) {
    std::string row = std::string("  ") + names[k] + "      ";
    for (int side = 0; side < 2; ++side) {
      for (const auto& r : kTableReflectances) {
        const double v = k == 0 ? r.ceiling : k == 1 ? r.walls : r.floor;
        std::snprintf(line, sizeof line, "%5.2f", v);
        row += line;
      }
      row += side == 0 ? "  |" : "";
    }
    out += row + "\n";
  }
  out += "  room X x Y   viewed crosswise           |  viewed endwise\n";
  for (size_t i = 0; i < kTableRooms.size(); ++i) {
    std::snprintf(line, sizeof line, "  %2.0fH x %2.0fH  ", kTableRooms[i].x_H, kTableRooms[i].y_H);
    std::string row = line;
    for (const auto& v : t.crosswise[i]) row += cell(v, t.correction);
    row += "  |";
    for (const auto& v : t.endwise[i]) row += cell(v, t.correction);
    out += row + "\n";
  }
  return out;
}

nlohmann::json ugr_table_json(const calc::glare::UgrTable& t) {
  nlohmann::json j;
  j["method"] = "CIE 190 tabular method, CIE 117 formula";
  j["spacing_H"] = calc::glare::kTableSpacingOverH;
  j["lamp_flux_lm"] = t.lamp_flux_lm;
  j["correction"] = t.correction;
  j["reflectances"] = nlohmann::json::array();
  for (const auto& r : kTableReflectances)
    j["reflectances"].push_back({r.ceiling, r.walls, r.floor});
  j["rooms"] = nlohmann::json::array();
  for (size_t i = 0; i < kTableRooms.size(); ++i) {
    j["rooms"].push_back({{"x_H", kTableRooms[i].x_H},
                          {"y_H", kTableRooms[i].y_H},
                          {"crosswise", values(t.crosswise[i], t.correction)},
                          {"endwise", values(t.endwise[i], t.correction)},
                          {"crosswise_1000lm", values(t.crosswise[i], 0.0)},
                          {"endwise_1000lm", values(t.endwise[i], 0.0)}});
  }
  return j;
}

}  // namespace luxgrid::cli
