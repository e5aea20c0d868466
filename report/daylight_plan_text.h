#pragma once
// The daylight scene's plan in words (calc/daylight_plan.h): the summary line, the notes that say
// what each component used and its error estimate, how the internally reflected component was
// computed and its flux balance, and the warnings (points in no room, the reflected light
// switched off). report/plan_text calls these when the plan has a daylight part and adds the
// reflected light's notes and the estimates per surface as for electric light.
#include <string>
#include <vector>

#include "calc/plan.h"

namespace luxgrid::report {

std::string daylight_summary(const calc::Plan& plan);
std::vector<std::string> daylight_notes(const calc::Plan& plan);
std::vector<std::string> daylight_warnings(const calc::Plan& plan);

}  // namespace luxgrid::report
