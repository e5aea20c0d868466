#pragma once
// Requirement checks, EN 12464-1 style: a calculation surface may carry
//   "requirements": { "Em": 500, "U0": 0.6, "Emin": 300, "Emax": 1000 }
// Em (maintained average illuminance, lx), U0 (Emin / Eavg) and Emin are lower limits; Emax is
// an upper limit (glare, over-lighting). UGR_L, on an observers surface only, is an upper limit
// on the surface's largest UGR (calc/glare). A value exactly at the limit meets it.
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calc/results.h"

namespace luxgrid::report {

// surface name -> quantity ("Em", "U0", "Emin", "Emax") -> limit
using Requirements = std::map<std::string, std::map<std::string, double>>;

// Reads the "requirements" of every entry of /surfaces in a raw project document. Throws
// InputError naming `label` and the JSON pointer: an unknown quantity
// (`p.json /surfaces/0/requirements/Eav: unknown quantity "Eav", expected Em, U0, Emin or Emax`),
// a value that is not a positive number, U0 above 1.
Requirements parse_requirements(const nlohmann::json& project, const std::string& label);

// Returns a copy of the project document without the "requirements" keys, for a loader that does
// not know them.
nlohmann::json without_requirements(const nlohmann::json& project);

struct RequirementCheck {
  std::string surface;
  std::string quantity;  // "Em", "U0", "Emin", "Emax", "UGR_L"
  double required = 0.0;
  double achieved = 0.0;
  bool upper_limit = false;  // Emax, UGR_L: achieved must not exceed required
  bool met = false;
  // How far inside (positive) or outside (negative) the limit, in the quantity's unit and as a
  // fraction of the limit: Em 520 against 500 gives +20 lx, +0.04.
  double margin = 0.0;
  double margin_rel = 0.0;
};

// Round-off guard: an average of values that sum exactly to the limit can come out one ulp
// below it (500 * (1 - 2e-16)); a relative slack of 1e-9 (0.5 ulx at 500 lx, far below any
// photometric accuracy) keeps "exactly at the limit" met.
inline constexpr double kAtLimitRelTol = 1e-9;

// One check per (surface, quantity), in surface order then Em, U0, Emin, Emax. Throws InputError
// if a requirement names a surface the results do not have.
std::vector<RequirementCheck> check_requirements(const calc::Results& results, const Requirements& req);

bool all_met(const std::vector<RequirementCheck>& checks);

// {"quantity", "required", "achieved", "met", "margin", "margin_rel", "limit": "min"|"max"}
nlohmann::json check_to_json(const RequirementCheck& c);

// Lines such as "workplane  Em  required >= 500 lx  achieved 512.3 lx  met (+12.3 lx, +2.5 %)".
std::string format_checks(const std::vector<RequirementCheck>& checks);

}  // namespace luxgrid::report
