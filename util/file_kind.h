#pragma once
// What a path names, found without opening it. Opening a FIFO for reading waits until a writer
// appears (POSIX open(2)), so a project naming one hung luxgrid; std::filesystem::status is
// stat(2), which never blocks. Every reader of a user's file asks here first, and names what
// the path is instead of "not found" (docs/reliability.md, "Error messages").
#include <filesystem>
#include <string>

namespace luxgrid {

// Empty when `path` is a regular file (or a link to one); otherwise what it is, as the end of a
// message: "file not found", "is a folder, not a file", "is a FIFO (named pipe), not a regular
// file", "is not a regular file (a device or a socket)".
inline std::string not_a_regular_file(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status s = fs::status(path, ec);
  switch (s.type()) {
    case fs::file_type::regular: return {};
    case fs::file_type::directory: return "is a folder, not a file";
    case fs::file_type::fifo: return "is a FIFO (named pipe), not a regular file";
    case fs::file_type::not_found:
    case fs::file_type::none: return "file not found";
    default: return "is not a regular file (a device or a socket)";
  }
}

}  // namespace luxgrid
