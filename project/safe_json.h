#pragma once
// The one JSON parse every reader of a project file goes through (the scene loader, the CLI's
// requirements, the fuzzer). nlohmann's own parse would accept what a hostile or broken file can
// do to us: a 200 MB file (8 GB of DOM), 100 000 nested objects (a stack overflow when the DOM
// is copied or destroyed), a key given twice (the last silently wins), 1e400 (an out_of_range
// exception nobody expects). This parse refuses each one while reading, naming the place.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "project/json_positions.h"

namespace luxgrid::project {

// The largest project file read, bytes. A big real project (20 000 luminaires written out one by
// one, ~100 bytes each) is 2 MB; nlohmann's DOM takes up to ~16 bytes per byte of dense text, so
// 16 MiB keeps the parsed document within ~256 MB and the parse under a second.
inline constexpr std::uintmax_t kMaxProjectFileBytes = 16u << 20;

// The deepest nesting of objects and arrays accepted, levels (the document itself is level 1).
// A project needs 6 (/surfaces/0/points/0/at); 64 leaves room for any extension, and keeps every
// recursive walk over the DOM (copy, destruction, dump) far from the stack's end.
inline constexpr int kMaxJsonDepth = 64;

// Parses JSON text. Throws InputError naming `label` and line:column for malformed JSON,
// nesting deeper than kMaxJsonDepth, a key repeated in one object (with its JSON pointer and the
// line of the first one) and numbers beyond the range of a double (with their pointer). Given
// `positions`, records where each value begins (project/json_positions.h).
nlohmann::json parse_json_text(std::string_view text, const std::string& label,
                               JsonPositions* positions = nullptr);

// The largest results.json read back (`luxgrid diff`), bytes: about 1.6 million points.
inline constexpr std::uintmax_t kMaxResultsFileBytes = 256u << 20;

// The bytes of `file`, refused before reading when larger than `max_bytes`; messages name the
// file as given and call it `kind`.
std::string read_bounded_file(const std::filesystem::path& file,
                              std::uintmax_t max_bytes = kMaxProjectFileBytes,
                              const std::string& kind = "project file");

// Reads `file` as read_bounded_file does and parses it as above.
nlohmann::json read_json_file(const std::filesystem::path& file,
                              std::uintmax_t max_bytes = kMaxProjectFileBytes,
                              const std::string& kind = "project file");

}  // namespace luxgrid::project
