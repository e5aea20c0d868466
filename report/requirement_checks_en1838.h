#pragma once
// The EN 1838 checks of the emergency scene [EN1838], made on every escape route and open area
// of the project (calc/emergency_surfaces.h) without being asked for:
//   escape route centre line: Emin >= 1 lx and Emax / Emin <= 40 (clause 4.2);
//   escape route central band: Emin >= 0.5 lx (clause 4.2);
//   open area (anti-panic) core: Emin >= 0.5 lx and Emax / Emin <= 40 (clause 4.3).
// They are RequirementChecks like EN 12464-1's, so the terminal, results.json, the report's
// compliance table and `--check` treat them alike (docs/compliance.md).
#include <vector>

#include "calc/results.h"
#include "report/requirement_checks.h"

namespace luxgrid::report {

// The quantity name of the diversity check, Emax / Emin.
inline constexpr const char* kDiversityQuantity = "Emax/Emin";

// In the order of `surfaces`. Throws InputError when a surface is missing from the results.
// Emax / Emin of a surface whose Emin is 0 is unbounded: "not calculated", with that reason.
std::vector<RequirementCheck> check_en1838(const calc::Results& results,
                                           const std::vector<calc::EmergencySurface>& surfaces);

}  // namespace luxgrid::report
