#include "photometry/table_warnings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "photometry/source_text.h"

namespace luxgrid::photometry {

namespace {

// (b) Intensities at the edge below 1 % of the maximum are the stray light a goniometer always
// sees (real corpus files: at most 0.4 % at the horizon, acme_road_dc0_dg0_isym3.ldt); above
// it, a measured cut-off would have reached zero before the table ends.
constexpr double kCutOffFraction = 0.01;
constexpr double kHorizonDeg = 90.0;
constexpr double kUpwardPoleDeg = 180.0;

std::string cd_text(double cd) {
  char buf[32];
  std::snprintf(buf, sizeof buf, cd >= 100 ? "%.0f" : "%.3g", cd);
  return buf;
}

std::string percent_text(double fraction) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f %%", 100.0 * fraction);
  return buf;
}

// The table's edge at gamma index j, `which` "ends" or "starts"; `beyond` says where no light
// goes ("at the horizon" or the cone it leaves dark).
void check_edge(const StoredPlanes& pl, std::size_t j, const char* which, const std::string& angle,
                const std::string& beyond, const std::string& name,
                std::vector<std::string>& warnings) {
  const std::size_t ng = pl.v_deg.size();
  const double peak = *std::max_element(pl.cd.begin(), pl.cd.end());
  double at = 0.0;
  for (std::size_t i = 0; i < pl.h_deg.size(); ++i) at = std::max(at, pl.cd[i * ng + j]);
  if (!(at > kCutOffFraction * peak)) return;
  warnings.push_back(name + ": the table " + which + " at gamma " + angle +
                     " with intensities up to " + cd_text(at) + " cd there (" +
                     percent_text(at / peak) + " of the maximum); the light is cut off abruptly " +
                     beyond);
}

}  // namespace

void check_all_zero(const StoredPlanes& pl, const std::string& name,
                    std::vector<std::string>& warnings) {
  if (pl.cd.empty()) return;
  if (std::any_of(pl.cd.begin(), pl.cd.end(), [](double cd) { return cd != 0.0; })) return;
  warnings.push_back(name +
                     ": every intensity of the table is 0 cd; the luminaire sends no light at all");
}

void check_cut_offs(const StoredPlanes& pl, const std::string& name,
                    std::vector<std::string>& warnings) {
  if (pl.v_deg.empty() || pl.cd.empty()) return;
  const std::size_t ng = pl.v_deg.size();
  const double first = pl.v_deg.front(), last = pl.v_deg.back();
  const auto is = [](double deg, double at) { return std::abs(deg - at) < kSameAngleDeg; };
  const std::string first_text = format_number(first), last_text = format_number(last);
  if (is(last, kHorizonDeg))
    check_edge(pl, ng - 1, "ends", "90", "at the horizon", name, warnings);
  else if (!is(last, kUpwardPoleDeg))
    check_edge(pl, ng - 1, "ends", last_text,
               "there (no light between gamma " + last_text + " and 180)", name, warnings);
  if (is(first, kHorizonDeg))
    check_edge(pl, 0, "starts", "90", "at the horizon", name, warnings);
  else if (!is(first, 0.0))
    check_edge(
        pl, 0, "starts", first_text,
        "there (no light between gamma 0 and " + first_text + ": a dark cone under the luminaire)",
        name, warnings);
}

void check_eulumdat_size_sign(double size_mm, const std::string& what, const std::string& where,
                              std::vector<std::string>& warnings) {
  if (!(size_mm < 0.0)) return;
  warnings.push_back(
      where + ": " + what + " " + format_number(size_mm) +
      " mm is negative, which EULUMDAT gives no meaning (a width of 0 is its circle); "
      "read as 0");
}

// LM-63-2002 Table 1 gives round openings as width and length both negative; the older files'
// "negative width, length 0" is read the old way (opening.cpp), with this note for newer ones.
constexpr int kFirstYearWithoutOldRoundRule = 2002;

void check_ies_size_signs(int year, double width_m, double length_m, double height_m,
                          const std::string& name, std::vector<std::string>& warnings) {
  if (year < kFirstYearWithoutOldRoundRule || !(width_m < 0.0) || length_m != 0.0 ||
      height_m != 0.0)
    return;
  warnings.push_back(name + ": luminous opening (" + format_number(width_m) + ", 0, 0) m: a " +
                     "negative width with length 0 is LM-63-1995's round opening, which LM-63-" +
                     std::to_string(year) + " does not define (its circle has width and length " +
                     "both negative); read as round, diameter " + format_number(-width_m) + " m");
}

}  // namespace luxgrid::photometry
