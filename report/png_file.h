#pragma once
// Writes a Raster as an 8-bit RGB PNG with libpng.
#include <filesystem>

#include "report/raster.h"

namespace luxgrid::report {

// Throws CalculationError naming `path` when the file cannot be written.
void write_png(const Raster& raster, const std::filesystem::path& path);

}  // namespace luxgrid::report
