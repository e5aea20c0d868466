#pragma once
// Project file v1 (docs/project-format.md) -> Project (the Scene and the requirements). Validation
// is strict: keys no reader takes, wrong types and impossible values are InputErrors naming the
// file and JSON pointer.
#include <filesystem>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "calc/scene.h"
#include "project/json_positions.h"
#include "project/requirements.h"

namespace luxgrid::project {

// Everything a project file says: the scene to calculate and what its surfaces must meet.
struct Project {
  calc::Scene scene;
  Requirements requirements;
};

inline constexpr const char* kProjectFormat = "luxgrid-project/1";

// Reads and parses `file` through the safe parse (project/safe_json.h): too large a file, malformed
// JSON, deep nesting, duplicate keys and out-of-range numbers are InputErrors with line:column.
Project load_project(const std::filesystem::path& file);

// The same from project text in memory (the fuzzer's entry point): `label` names it in every
// message, relative photometry paths are resolved against `base_dir`.
Project parse_project_text(std::string_view text, const std::string& label,
                           const std::filesystem::path& base_dir);

// Parses an already-read document (read it with read_json_file or parse_json_text, which
// bound its size and depth). `label` names it in messages; relative photometry paths are
// resolved against `base_dir`. With the positions its parse recorded, messages name each value's
// line and column too.
Project parse_project(const nlohmann::json& doc, const std::string& label,
                      const std::filesystem::path& base_dir,
                      const JsonPositions* positions = nullptr);

}  // namespace luxgrid::project
