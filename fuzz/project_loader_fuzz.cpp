// libFuzzer target: any bytes given to the project loader either load or throw InputError, in
// bounded memory and time (the loader's limits, docs/reliability.md); a loaded scene holds finite
// positions only. Anything else (a crash, another exception, a sanitizer report) is a bug.
// Photometry paths resolve in an empty folder, so no file outside it is read.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string_view>

#include "project/project_file.h"
#include "util/error.h"

namespace {
const std::filesystem::path& empty_folder() {
  static const std::filesystem::path dir = [] {
    auto d = std::filesystem::temp_directory_path() / "luxgrid_project_fuzz_empty";
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto scene =
        luxgrid::project::parse_project_text(text, "fuzz.json", empty_folder()).scene;
    for (const auto& l : scene.luminaires) {
      const auto& p = l.pose.position;
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) std::abort();
    }
  } catch (const luxgrid::InputError&) {
  }
  return 0;
}
