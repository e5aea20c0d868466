#pragma once
// Project file v1 (docs/project-format.md) -> Scene. Validation is strict: unknown keys, wrong
// types and impossible values are InputErrors naming the file and JSON pointer.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "calc/scene.h"

namespace luxgrid::calc {

inline constexpr const char* kProjectFormat = "luxgrid-project/1";

// Reads and parses `file`; malformed JSON is reported with line and column.
Scene load_project(const std::filesystem::path& file);

// Parses an already-read document. `label` names it in messages; relative photometry paths are
// resolved against `base_dir`.
Scene parse_project(const nlohmann::json& doc, const std::string& label,
                    const std::filesystem::path& base_dir);

}  // namespace luxgrid::calc
