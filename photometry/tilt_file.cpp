#include "photometry/tilt_file.h"

#include <algorithm>

#include "photometry/file_bytes.h"
#include "photometry/limits.h"
#include "util/error.h"

namespace luxgrid::photometry {

std::string read_tilt_file(const SourceText& ies, int tilt_line, std::string_view value,
                           const std::filesystem::path& ies_dir,
                           const std::filesystem::path& allowed_root,
                           std::filesystem::path& path_out) {
  // The name is quoted in every message below, so it must be safe to quote (limits.h).
  const bool printable = std::all_of(value.begin(), value.end(), [](char ch) {
    return static_cast<unsigned char>(ch) >= 0x20 && static_cast<unsigned char>(ch) < 0x7F;
  });
  if (!printable || value.size() > kMaxTiltNameChars)
    ies.fail(tilt_line, "expected NONE, INCLUDE or a file name of at most " +
                            std::to_string(kMaxTiltNameChars) +
                            " printable ASCII characters after TILT=, found " +
                            (printable ? "a " + std::to_string(value.size()) + "-character name"
                                       : std::string("bytes that are not printable ASCII")));
  const std::string quoted = "'" + std::string(value) + "'";
  // operator/ keeps an absolute name as it is; a relative one is read beside the IES file.
  const std::filesystem::path path = ies_dir / std::filesystem::path(value);
  if (!lies_within(path, allowed_root))
    ies.fail(tilt_line, "TILT file " + quoted +
                            " lies outside the project folder; refused (a TILT file must be in "
                            "the folder of the project or below it)");
  // Named in messages beside the IES file as the messages name that one (as the project writes
  // it), not by the path opened.
  const std::string shown =
      (std::filesystem::path(ies.name()).parent_path() / std::filesystem::path(value)).string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    ies.fail(tilt_line, "TILT file " + quoted + " not found (looked for " + shown + ")");
  path_out = path;
  try {
    std::string bytes = read_bounded_file(path, shown, kMaxTiltFileBytes, "TILT");
    if (bytes.empty()) throw InputError(SourceLocation{shown}, "file is empty");
    check_is_text(bytes, shown, "TILT data");
    return bytes;
  } catch (const InputError& e) {
    ies.fail(tilt_line, "TILT file " + quoted + ": " + e.what());
  }
}

}  // namespace luxgrid::photometry
