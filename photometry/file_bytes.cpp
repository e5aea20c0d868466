#include "photometry/file_bytes.h"

#include <fstream>

#include "util/error.h"
#include "util/file_kind.h"

namespace luxgrid::photometry {

namespace {
// How much of a file the text test looks at: enough for any header, cheap for any file.
constexpr std::size_t kTextProbeBytes = 4096;
// Text has at most one control byte (other than tab, CR, LF, FF) in ten; binary data has many.
constexpr std::size_t kMaxControlBytesPerTen = 1;
constexpr std::size_t kReadChunkBytes = 64u << 10;
}  // namespace

void check_size(std::size_t size, const std::string& name, std::size_t max_bytes,
                const char* kind) {
  if (size > max_bytes)
    throw InputError(SourceLocation{name}, "file is " + std::to_string(size) + " bytes; " + kind +
                                               " files are expected below " +
                                               std::to_string(max_bytes) + " bytes");
}

std::string read_bounded_file(const std::filesystem::path& file, const std::string& name,
                              std::size_t max_bytes, const char* kind) {
  // By stat, before any open (util/file_kind.h): a FIFO would block the open.
  if (const std::string what = not_a_regular_file(file); !what.empty())
    throw InputError(SourceLocation{name}, what);
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) throw InputError(SourceLocation{name}, "cannot read the file size: " + ec.message());
  check_size(static_cast<std::size_t>(size), name, max_bytes, kind);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(SourceLocation{name}, "cannot open the file");
  // Read in chunks and stop past the limit: the file may have grown since its size was taken,
  // and files under /proc report size 0 whatever they hold.
  std::string bytes;
  char chunk[kReadChunkBytes];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    bytes.append(chunk, static_cast<std::size_t>(in.gcount()));
    check_size(bytes.size(), name, max_bytes, kind);
  }
  return bytes;
}

void check_is_text(std::string_view bytes, const std::string& name, const char* expected) {
  const std::string_view head = bytes.substr(0, kTextProbeBytes);
  std::size_t control = 0;
  bool nul = false;
  for (char ch : head) {
    const auto c = static_cast<unsigned char>(ch);
    nul = nul || c == 0;
    if (c < 0x20 && c != '\n' && c != '\r' && c != '\t' && c != '\f') ++control;
  }
  if (nul || control * 10 > head.size() * kMaxControlBytesPerTen)
    throw InputError(SourceLocation{name},
                     std::string("expected a text file (") + expected + "), found binary data");
}

}  // namespace luxgrid::photometry
