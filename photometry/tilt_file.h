#pragma once
// Where an IES TILT=<file> may be, and what of it may be read. The rule, for users:
//  * the name is relative to the folder of the IES file that names it (LM-63 keeps the tilt
//    data beside the photometry), whatever the current directory;
//  * after resolving "..", "." and symbolic links it must lie inside the allowed root (the
//    project folder; for `luxgrid info FILE`, FILE's folder) unless the root is empty;
//  * it must be a regular file below kMaxTiltFileBytes, checked before it is read, and text.
// Every error names the IES file and the line of its TILT= ("panel.ies:3: TILT file
// 'lamp.tilt': ..."), then, for errors inside the TILT file, that file and its line.
#include <filesystem>
#include <string>
#include <string_view>

#include "photometry/source_text.h"
#include "util/paths.h"

namespace luxgrid::photometry {

// The bytes of the TILT file named by `value` on line `tilt_line` of `ies`, or InputError as
// above. `ies_dir` is the IES file's folder, `allowed_root` as LoadOptions::allowed_root.
// `path_out` receives the path the file was read from (for messages and TiltTable::source).
std::string read_tilt_file(const SourceText& ies, int tilt_line, std::string_view value,
                           const std::filesystem::path& ies_dir,
                           const std::filesystem::path& allowed_root,
                           std::filesystem::path& path_out);

}  // namespace luxgrid::photometry
