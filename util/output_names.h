#pragma once
// The names of the files a calculation surface writes into the output folder. The project loader
// checks them for collisions before anything runs and report/write_outputs.cpp writes exactly
// these, so the two cannot drift.
#include <array>
#include <cctype>
#include <string>

namespace luxgrid {

// A file-system-safe name for a surface: letters, digits, '-', '_' and '.' kept, others '_'.
inline std::string safe_file_name(const std::string& name) {
  std::string out;
  for (unsigned char c : name) {
    out += (std::isalnum(c) || c == '-' || c == '_' || c == '.') ? static_cast<char>(c) : '_';
  }
  return out.empty() ? "surface" : out;
}

// Every file one surface may write: the CSV always, the plots for grids, the direct and indirect
// plots when reflected light ran, the .npy array when asked for. The loader reserves all of them
// for every surface, so whether two surfaces collide does not depend on the settings.
struct SurfaceOutputFiles {
  std::string csv, png, direct_png, indirect_png, npy;
  auto all() const {
    return std::array<const std::string*, 5>{&csv, &png, &direct_png, &indirect_png, &npy};
  }
};

inline SurfaceOutputFiles surface_output_files(const std::string& surface_name) {
  const std::string base = safe_file_name(surface_name);
  return {base + ".csv", base + ".png", base + "_direct.png", base + "_indirect.png",
          base + ".npy"};
}

// Files of the folder itself, which no surface may overwrite.
inline constexpr const char* kResultsFile = "results.json";
inline constexpr const char* kReportFile = "report.html";
inline constexpr const char* kTimingFile = "timing.json";  // phase times, apart from the results
inline constexpr const char* kSceneFile = "scene.glb";     // the 3D scene (report/scene_glb.h)
inline constexpr const char* kFolderOutputFiles[] = {kResultsFile, kReportFile, kTimingFile,
                                                     kSceneFile};

}  // namespace luxgrid
