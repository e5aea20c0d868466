#pragma once
// The two file readers behind load_photometry_file. Each takes the bytes of a file and a name for
// messages, and returns a complete Photometry (distribution expanded to the full sphere).
#include <filesystem>
#include <string>
#include <string_view>

#include "photometry/limits.h"
#include "photometry/photometry.h"

namespace luxgrid::photometry {

// IES LM-63-1986/1991/1995/2002/2019. `tilt_dir` is where TILT=<file> is looked for (the IES
// file's folder); `options.allowed_root` bounds where it may lie (tilt_file.h).
Photometry read_ies(std::string_view bytes, const std::string& name,
                    const std::filesystem::path& tilt_dir, const LoadOptions& options);

// EULUMDAT (.ldt), all symmetry indicators.
Photometry read_eulumdat(std::string_view bytes, const std::string& name);

}  // namespace luxgrid::photometry
