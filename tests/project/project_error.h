#pragma once
// The loader's refusal of a project document, as text ("(no error)" when it loads), for tests
// that compare the exact message.
#include <string>

#include "project/project_file.h"
#include "util/error.h"

namespace luxgrid::project {
using namespace calc;

inline std::string error_of(const nlohmann::json& doc) {
  try {
    (void)parse_project(doc, "p.json", ".");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace luxgrid::project
