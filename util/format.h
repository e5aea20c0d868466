#pragma once
// Numbers as text for messages, plan lines and the report: one place for the two forms used.
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

}  // namespace luxgrid
