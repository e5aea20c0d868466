#pragma once
// The two file readers behind load_photometry_file. Each takes the bytes of a file and a name for
// messages, and returns a complete Photometry (distribution expanded to the full sphere).
#include <filesystem>
#include <string>
#include <string_view>

#include "photometry/photometry.h"

namespace luxgrid::photometry {

// IES LM-63-1986/1991/1995/2002/2019. `tilt_dir` is where TILT=<file> is looked for.
Photometry read_ies(std::string_view bytes, const std::string& name,
                    const std::filesystem::path& tilt_dir);

// EULUMDAT (.ldt), all symmetry indicators.
Photometry read_eulumdat(std::string_view bytes, const std::string& name);

// Limits that keep hostile headers from allocating without bound (the header is checked before
// any table is read; real files stay far below: the largest in the corpus has 94,943 values).
inline constexpr long kMaxAngles = 100000;
inline constexpr long kMaxValues = 10000000;

}  // namespace luxgrid::photometry
