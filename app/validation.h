#pragma once
// The validation runner: each folder under cases/ with a project.json and an expected.json is
// calculated and its values compared with the expected ones (docs/validation.md).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calc/scene.h"

namespace luxgrid::app {

struct CheckRow {
  std::string case_name;
  std::string quantity;  // e.g. "probes[3].E" or "workplane.Eavg"
  double expected = 0.0;
  double got = 0.0;
  double error = 0.0;      // (got - expected) / |expected|, or got - expected when expected is 0
  double tolerance = 0.0;  // absolute, lx: max(rel_tol * |expected|, abs_tol)
  std::string tolerance_text;
  bool pass = false;
  std::string source;
};

struct ValidationReport {
  std::vector<CheckRow> rows;
  std::vector<std::string> case_errors;  // cases that could not run at all
  // Cases under CASES_DIR/pending/: written, not yet run, because a capability they need is not
  // built; listed in every table so they are never forgotten (cases/pending/README.md).
  std::vector<std::string> pending;
  std::optional<calc::Quality> quality;  // run_validation's, when given
  bool all_passed() const;
  std::string markdown() const;
  nlohmann::json json() const;
};

// Runs every case under `cases_dir`; each case's outputs go to out_dir/<case>/. With `quality`,
// every case runs at that quality (standard or high, the qualities with a promise) and each check
// of a relative tolerance no looser than standard's promise is held to the quality's promise
// where that is tighter (docs/validation.md, "At a quality").
ValidationReport run_validation(const std::filesystem::path& cases_dir,
                                const std::filesystem::path& out_dir,
                                std::optional<calc::Quality> quality = std::nullopt);

}  // namespace luxgrid::app
