// load_photometry_file: picks the reader by content first (an IES version tag, a TILT= line),
// then by extension, and refuses what is not text at all.
#include <algorithm>
#include <cctype>

#include "photometry/file_bytes.h"
#include "photometry/file_warnings.h"
#include "photometry/photometry.h"
#include "photometry/readers.h"
#include "photometry/source_text.h"
#include "util/error.h"

namespace luxgrid::photometry {

const char* to_string(PhotometricType t) {
  switch (t) {
    case PhotometricType::C: return "C";
    case PhotometricType::B: return "B";
    case PhotometricType::A: return "A";
  }
  return "?";
}

const char* to_string(Symmetry s) {
  switch (s) {
    case Symmetry::none: return "none";
    case Symmetry::rotational: return "rotational";
    case Symmetry::bilateral_c0_c180: return "bilateral C0-C180";
    case Symmetry::bilateral_c90_c270: return "bilateral C90-C270";
    case Symmetry::quadrant: return "quadrant";
  }
  return "?";
}

namespace {

std::string lower_extension(const std::string& name) {
  std::string ext = std::filesystem::path(name).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

bool looks_like_ies(std::string_view bytes) {
  std::string_view head = bytes.substr(0, 4096);
  if (head.substr(0, 3) == "\xEF\xBB\xBF") head.remove_prefix(3);
  std::string up(head.substr(0, 8));
  for (char& c : up) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (up.rfind("IESNA", 0) == 0 || up.rfind("IES:", 0) == 0) return true;
  // LM-63-1986 has no tag: its TILT= line gives it away.
  std::string all(bytes.substr(0, 65536));
  for (char& c : all) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return all.find("\nTILT") != std::string::npos || all.find("\rTILT") != std::string::npos;
}

// `name` in messages; `dir`: where a TILT=<file> is looked for.
Photometry load_from_bytes(std::string_view bytes, const std::string& name,
                           const std::filesystem::path& dir, const LoadOptions& options) {
  if (bytes.empty()) throw InputError(SourceLocation{name}, "file is empty");
  // Photometric files are text: NUL bytes or mostly control bytes mean something else.
  check_is_text(bytes, name, "IES or EULUMDAT");
  Photometry p = looks_like_ies(bytes) || lower_extension(name) == ".ies"
                     ? read_ies(bytes, name, dir, options)
                     : read_eulumdat(bytes, name);
  check_stated_ratios(p);
  return p;
}

}  // namespace

Photometry load_photometry_text(std::string_view bytes, const std::string& name,
                                const LoadOptions& options) {
  return load_from_bytes(bytes, name, std::filesystem::path(name).parent_path(), options);
}

Photometry load_photometry_file(const std::filesystem::path& file, const LoadOptions& options) {
  const std::string name = options.name.empty() ? file.string() : options.name;
  return load_from_bytes(read_bounded_file(file, name, kMaxPhotometryFileBytes, "photometric"),
                         name, file.parent_path(), options);
}

}  // namespace luxgrid::photometry
