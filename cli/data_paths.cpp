#include "cli/data_paths.h"

#include <vector>

namespace luxgrid::cli {

namespace fs = std::filesystem;

fs::path find_repository_path(const std::string& relative) {
  std::vector<fs::path> roots;
  std::error_code ec;
  // Linux: the running binary, whatever the current folder or the name it was started by.
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) roots.push_back(self.parent_path().parent_path());
#ifdef LUXGRID_SOURCE_DIR
  roots.emplace_back(LUXGRID_SOURCE_DIR);
#endif
  for (const auto& root : roots) {
    const fs::path candidate = root / relative;
    if (fs::exists(candidate, ec)) return candidate;
  }
  return relative;
}

}  // namespace luxgrid::cli
