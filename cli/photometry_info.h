#pragma once
// What `luxgrid info FILE` reads and derives from a photometric file, and its `--json` document:
// shared by the command (cli/info_command.cpp) and the Python module's `luxgrid.info` (python/).
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calc/glare/ugr_table.h"
#include "photometry/derived_photometry.h"
#include "photometry/photometry.h"

namespace luxgrid::cli {

// A direction asked for with --at: C and gamma in degrees.
struct InfoAt {
  double c_deg, gamma_deg;
};

struct PhotometryInfo {
  photometry::Photometry photometry;
  photometry::DerivedPhotometry derived;
  std::optional<calc::glare::UgrTable> ugr_table;  // --ugr only
  std::vector<InfoAt> at;
  std::vector<double> intensity_cd;  // at each of `at`
};

// Reads `file` (a TILT file it names must lie in its folder or below), with bicubic
// interpolation when `interpolation` is "bicubic", and derives what `info` prints.
PhotometryInfo read_photometry_info(const std::string& file, const std::vector<InfoAt>& at,
                                    const std::string& interpolation, bool ugr);

// The `info --json` document (docs/photometry.md).
nlohmann::json photometry_info_json(const PhotometryInfo& info);

}  // namespace luxgrid::cli
