#pragma once
// Project file v1 (docs/project-format.md) -> Scene. Validation is strict: unknown keys, wrong
// types and impossible values are InputErrors naming the file and JSON pointer.
#include <filesystem>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "calc/scene.h"

namespace luxgrid::calc {

inline constexpr const char* kProjectFormat = "luxgrid-project/1";

// Reads and parses `file` through the safe parse (calc/safe_json.h): too large a file, malformed
// JSON, deep nesting, duplicate keys and out-of-range numbers are InputErrors with line:column.
Scene load_project(const std::filesystem::path& file);

// The same from project text in memory (the fuzzer's entry point): `label` names it in every
// message, relative photometry paths are resolved against `base_dir`.
Scene parse_project_text(std::string_view text, const std::string& label,
                         const std::filesystem::path& base_dir);

// Parses an already-read document (read it with calc::read_json_file or parse_json_text, which
// bound its size and depth). `label` names it in messages; relative photometry paths are
// resolved against `base_dir`.
Scene parse_project(const nlohmann::json& doc, const std::string& label,
                    const std::filesystem::path& base_dir);

}  // namespace luxgrid::calc
