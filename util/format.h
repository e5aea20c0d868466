#pragma once
// One number formatted with a printf format ("%.4g", "%.3g lx"), for messages and plan lines.
#include <cstdio>
#include <string>

namespace luxgrid {

inline std::string format_double(const char* printf_format, double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, printf_format, value);
  return buf;
}

}  // namespace luxgrid
