// load_photometry_file: picks the reader by content first (an IES version tag, a TILT= line),
// then by extension, and refuses what is not text at all.
#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

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

}  // namespace

Photometry load_photometry_text(std::string_view bytes, const std::string& name) {
  if (bytes.empty()) throw InputError(name + ": file is empty");
  // Photometric files are text: NUL bytes or mostly control bytes mean something else.
  const std::string_view head = bytes.substr(0, 4096);
  std::size_t control = 0;
  for (char ch : head) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == 0) throw InputError(name + ": expected a text file (IES or EULUMDAT), found binary data");
    if (c < 0x20 && c != '\n' && c != '\r' && c != '\t' && c != '\f') ++control;
  }
  if (control * 10 > head.size())
    throw InputError(name + ": expected a text file (IES or EULUMDAT), found binary data");

  const std::string ext = lower_extension(name);
  const std::filesystem::path dir = std::filesystem::path(name).parent_path();
  if (looks_like_ies(bytes)) return read_ies(bytes, name, dir);
  if (ext == ".ies") return read_ies(bytes, name, dir);
  return read_eulumdat(bytes, name);
}

Photometry load_photometry_file(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) throw InputError(name + ": file not found");
  if (!std::filesystem::is_regular_file(file, ec))
    throw InputError(name + ": not a regular file");
  const auto size = std::filesystem::file_size(file, ec);
  if (!ec && size > kMaxPhotometryFileBytes)
    throw InputError(name + ": file is " + std::to_string(size) +
                     " bytes; photometric files are expected below " +
                     std::to_string(kMaxPhotometryFileBytes) + " bytes");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(name + ": cannot open the file");
  std::ostringstream s;
  s << in.rdbuf();
  return load_photometry_text(s.str(), name);
}

}  // namespace luxgrid::photometry
