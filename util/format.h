#pragma once
// Numbers as text for messages, plan lines and the report: every number luxgrid writes as text
// (but the CSV's and results.json's values, report/number_text_memo.h) goes through here.
#include <charconv>
#include <cstdio>
#include <string>

namespace luxgrid {

// One number formatted with a printf format ("%.4g", "%.3g lx").
inline std::string format_double(const char* printf_format, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, printf_format, value);
  return buf;
}

// The shortest decimal that reads back to the same double (std::to_chars): what a file or a
// project said, quoted in a message.
inline std::string format_number(double value) {
  char buf[64];  // the longest double, "-2.2250738585072014e-308", has 24 characters
  const auto r = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, r.ptr);
}

// A number for a message: %g, so 0 and 1 print as "0" and "1" and 1e9 as "1e+09".
inline std::string number_text(double value) { return format_double("%g", value); }

}  // namespace luxgrid
