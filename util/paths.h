#pragma once
// Whether a path lies inside a folder, for every rule that keeps luxgrid inside the folders it
// may read or replace (photometry and TILT files inside the project folder, inputs outside an
// output folder). One copy, so the rules cannot drift apart.
#include <filesystem>

namespace luxgrid {

// True when `path` is `root` or lies below it, both taken through weakly_canonical (so ".." and
// symbolic links cannot climb out), compared component by component (so "/data/project2" is not
// inside "/data/project"). An empty root allows everything; a path that cannot be resolved lies
// nowhere.
inline bool lies_within(const std::filesystem::path& path, const std::filesystem::path& root) {
  if (root.empty()) return true;
  std::error_code ec;
  const std::filesystem::path p =
      std::filesystem::weakly_canonical(std::filesystem::absolute(path), ec);
  if (ec) return false;
  const std::filesystem::path r =
      std::filesystem::weakly_canonical(std::filesystem::absolute(root), ec);
  if (ec) return false;
  auto pi = p.begin();
  for (auto ri = r.begin(); ri != r.end(); ++ri, ++pi) {
    if (ri->empty()) continue;  // the trailing "" of a root written with a final slash
    if (pi == p.end() || *pi != *ri) return false;
  }
  return true;
}

}  // namespace luxgrid
