#pragma once
// The report's compliance table: per task area, wall, ceiling and floor the required and achieved
// Em, U0, Emin, Emax, Ez, Esc, modelling, UGR_L and Ra, each met / not met / not calculated with
// its margin, and the source of every preset limit (docs/compliance.md).
#include <string>
#include <vector>

#include "report/requirement_checks.h"

namespace luxgrid::report {

// The HTML section (an <h2>, the verdict and the table); empty for no checks.
std::string compliance_table_html(const std::vector<RequirementCheck>& checks);

// The report's "Scene" row for the emergency scene (empty for the normal one).
std::string lighting_scene_row_html(calc::LightingScene scene);

// "met", "not met" or "not calculated".
const char* check_result(const RequirementCheck& c);

}  // namespace luxgrid::report
