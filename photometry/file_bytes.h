#pragma once
// Reading a file that should be small text (a photometric file, a TILT file) without trusting
// it: its size is checked before a byte is read, it must be a regular file (not a directory, a
// FIFO or /dev/zero), and text it must be. Messages name the file, never quote its bytes.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace luxgrid::photometry {

// The whole file, or InputError "name: ..." when it is missing, not a regular file, larger than
// `max_bytes` ("name: file is N bytes; <kind> files are expected below M bytes") or unreadable.
// `kind` names what the file should be, e.g. "photometric" or "TILT".
std::string read_bounded_file(const std::filesystem::path& file, const std::string& name,
                              std::size_t max_bytes, const char* kind);

// The same size rule for bytes already in memory.
void check_size(std::size_t size, const std::string& name, std::size_t max_bytes, const char* kind);

// InputError "name: expected a text file (<expected>), found binary data" when `bytes` hold a
// NUL or mostly control bytes. `expected` says what text, e.g. "IES or EULUMDAT".
void check_is_text(std::string_view bytes, const std::string& name, const char* expected);

}  // namespace luxgrid::photometry
