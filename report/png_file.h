#pragma once
// Writes a Raster as an 8-bit RGB PNG: the chunks written here, the image data compressed by
// libdeflate.
#include <filesystem>
#include <string>

#include "report/raster.h"

namespace luxgrid::report {

// Throws CalculationError naming `path` when the file cannot be written. Returns the bytes
// written (report.html embeds them without reading the file back).
std::string write_png(const Raster& raster, const std::filesystem::path& path);

// The same PNG as bytes in memory (for images embedded in report.html).
std::string encode_png(const Raster& raster);

}  // namespace luxgrid::report
