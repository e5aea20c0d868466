#pragma once
// report.html's EN 17037 daylight provision table [EN17037]: per reference plane its average
// daylight factor and uniformity, and per level the daylight factor each target asks for at the
// site, the share of the plane reaching it, the share required and the verdict; the level
// asked marked (docs/daylight.md).
#include <string>

#include "calc/daylight/en17037.h"

namespace luxgrid::report {

std::string en17037_table_html(const daylight::En17037Assessment& a);

}  // namespace luxgrid::report
