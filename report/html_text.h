#pragma once
// Text for the HTML report and the SVG drawn into it: escaping and the one font family both use
// (the same DejaVu Sans the PNG plots are set in, report/raster_text.h).
#include <string>

namespace luxgrid::report {

// CSS font-family list for report.html and its inline SVG.
inline constexpr const char* kReportFontFamily = "\"DejaVu Sans\", Helvetica, Arial, sans-serif";

// Text safe inside HTML/SVG elements and attribute values.
std::string html_escape(const std::string& s);

}  // namespace luxgrid::report
