#pragma once
// Requirement checks, EN 12464-1 style [EN12464-1]: the results against the Requirements read
// with the project (project/requirements.h describes the keys). Em, U0, Emin, Ez, Esc and Ra are
// lower limits; Emax and UGR_L upper limits; modelling a range. A value exactly at the limit
// meets it. docs/compliance.md is the user's reference.
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "calc/results.h"
#include "project/requirements.h"

namespace luxgrid::report {

// The requirements as read with the project (project/requirements.h).
using project::parse_requirements;
using project::Requirements;
using project::SurfaceRequirements;

// What the results alone do not hold: the lamps' colour rendering index
// (report/colour_rendering.h).
struct ComplianceInputs {
  std::optional<double> Ra;
  std::string Ra_source;  // where Ra came from, or why it is unknown
};

struct RequirementCheck {
  std::string surface;
  std::string role;      // "task area", "wall", "ceiling", "floor"
  std::string quantity;  // "Em", "U0", "Emin", "Emax", "Ez", "Esc", "modelling", "UGR_L", "Ra"
  double required = 0.0;
  std::optional<double> required_max;  // modelling: the upper end of the range
  double achieved = 0.0;               // modelling: the smallest ratio over the points
  std::optional<double> achieved_max;  // modelling: the largest ratio
  bool upper_limit = false;            // Emax, UGR_L: achieved must not exceed required
  bool calculated = true;  // false: nothing gives the value (no observers surface, Ra unknown)
  bool met = false;        // never true when not calculated
  // How far inside (positive) or outside (negative) the limit, in the quantity's unit and as a
  // fraction of the limit: Em 520 against 500 gives +20 lx, +0.04. Modelling: the smaller of
  // (min ratio - lo) and (hi - max ratio).
  double margin = 0.0;
  double margin_rel = 0.0;
  std::string source;  // the preset row that set the limit, the standard's clause, or empty for an
                       // explicit one
  // The limit is the standard's own, not a project's choice (EN 1838's checks of the emergency
  // scene, report/requirement_checks_en1838.h): `source` cites the clause.
  bool fixed_by_standard = false;
  std::string note;  // where the achieved value comes from, or why it was not calculated
};

// Round-off guard: an average of values that sum exactly to the limit can come out one ulp
// below it (500 * (1 - 2e-16)); a relative slack of 1e-9 (0.5 ulx at 500 lx, far below any
// photometric accuracy) keeps "exactly at the limit" met.
inline constexpr double kAtLimitRelTol = 1e-9;

// Modelling pairs a cylindrical and a horizontal surface point by point: their points may differ
// by at most this much (1 mm, far below any grid spacing; the same grid built twice agrees to
// round-off).
inline constexpr double kModellingPairTolerance_m = 1e-3;

// Checks in surface order, then Em, U0, Emin, Emax, Ez, Esc, modelling, UGR_L, Ra. Throws
// InputError if a requirement names a surface the results do not have, or modelling pairs
// surfaces whose points differ.
std::vector<RequirementCheck> check_requirements(const calc::Results& results,
                                                 const Requirements& req,
                                                 const ComplianceInputs& inputs = {});

// True when every check was calculated and met.
bool all_met(const std::vector<RequirementCheck>& checks);

// {"quantity", "required", "achieved", "met", "calculated", "margin", "margin_rel",
//  "limit": "min"|"max"|"range", "role", and where given "required_max", "achieved_max",
//  "source", "note"}
nlohmann::json check_to_json(const RequirementCheck& c);

// Lines such as "workplane  Em  required >= 500 lx  achieved 512.3 lx  met (+12.3 lx, +2.5 %)".
std::string format_checks(const std::vector<RequirementCheck>& checks);

// " lx" for illuminances, "" for ratios and indices.
std::string requirement_unit(const std::string& quantity);

}  // namespace luxgrid::report
