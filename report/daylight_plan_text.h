#pragma once
// The daylight scene's plan in words (calc/daylight_plan.h): the summary line, the notes that say
// what each component used and its error estimate, and the warnings (an estimate above the
// quality's promise, points in no room, what is not built yet). report/plan_text calls these
// when the plan has a daylight part.
#include <string>
#include <vector>

#include "calc/plan.h"

namespace luxgrid::report {

std::string daylight_summary(const calc::Plan& plan);
std::vector<std::string> daylight_notes(const calc::Plan& plan);
std::vector<std::string> daylight_warnings(const calc::Plan& plan);

}  // namespace luxgrid::report
