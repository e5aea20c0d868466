#pragma once
// The report's table for an observers surface: per observer and view the line of sight, UGR,
// background luminance and the illuminance at the eye, and the surface's largest UGR.
#include <string>

#include "calc/results.h"

namespace luxgrid::report {

// UGR as the report prints it ("%.1f"; "&ndash;" for a view without any luminaire in it).
std::string format_ugr_value(const std::optional<double>& ugr);

std::string observers_html(const calc::SurfaceResult& s);

}  // namespace luxgrid::report
