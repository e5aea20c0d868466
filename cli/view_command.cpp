// `luxgrid view PROJECT [-o FILE]`: the project in 3D without calculating, to check the input
// (rooms, obstacles, luminaires with their C0 arrows and photometric solids, calculation
// surfaces): a page with the 3D view (FILE.html, the default `<project>.view.html` beside the
// project) or the scene as glTF (FILE.glb), as report.html and scene.glb show it (docs/report.md).
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli/commands.h"
#include "project/project_file.h"
#include "report/embedded_scripts.h"
#include "report/luminaire_types.h"
#include "report/output_folder.h"
#include "report/scene_glb.h"
#include "report/scene_view_html.h"
#include "util/error.h"

namespace luxgrid::cli {

namespace {

// The first `n` bytes of `path` (fewer when it is shorter).
std::string file_head(const std::filesystem::path& path, std::size_t n) {
  std::ifstream f(path, std::ios::binary);
  std::string head(n, '\0');
  f.read(head.data(), static_cast<std::streamsize>(n));
  head.resize(static_cast<std::size_t>(std::max<std::streamsize>(f.gcount(), 0)));
  return head;
}

bool written_by_view(const std::filesystem::path& path, bool glb) {
  if (!glb) return file_head(path, 4096).find(report::kViewPageTag) != std::string::npos;
  // A glb: a 12-byte header, then the JSON chunk's length (little-endian) and type, then the JSON.
  const std::string header = file_head(path, 20);
  if (header.size() < 20 || header.compare(0, 4, "glTF") != 0) return false;
  std::uint32_t json_bytes = 0;
  for (int k = 3; k >= 0; --k)
    json_bytes = (json_bytes << 8) | static_cast<unsigned char>(header[12 + k]);
  constexpr std::uint32_t kMaxJsonBytes = 64u << 20;  // luxgrid's scenes stay far below
  if (json_bytes > kMaxJsonBytes) return false;
  return file_head(path, 20 + json_bytes).find("\"generator\":\"luxgrid ") != std::string::npos;
}

}  // namespace

int run_view(const ViewArgs& args) {
  namespace fs = std::filesystem;
  const fs::path project_file = args.project;
  fs::path out = args.out;
  if (out.empty()) out = fs::path(project_file).replace_extension(".view.html");
  const std::string ext = out.extension().string();
  if (ext != ".html" && ext != ".htm" && ext != ".glb")
    throw InputError(out.string() + ": the file must end in .html or .glb");
  // Never over a file of the user's: only over what an earlier `luxgrid view` wrote (its page tag
  // at the head of the page, or a glb whose JSON chunk names luxgrid its generator).
  if (fs::exists(out) && !written_by_view(out, ext == ".glb"))
    throw InputError(SourceLocation{out.string()},
                     "exists and was not written by luxgrid view: not overwritten (choose "
                     "another file with -o, or remove it)");
  const project::Project loaded = project::load_project(project_file);
  const calc::Scene& scene = loaded.scene;
  for (const auto& w : scene.warnings)
    std::fprintf(stderr, "luxgrid: warning: %s\n", w.text().c_str());
  const std::vector<report::LuminaireType> types = report::luminaire_types(scene);
  report::SceneGlbInput in;
  in.scene = &scene;
  in.types = &types;
  in.version = LUXGRID_VERSION;
  const std::string glb = report::scene_glb(in);
  if (ext == ".glb") {
    report::write_text_file(out, glb);
  } else {
    report::SceneViewOptions view;
    view.show = "rooms,surfaces,luminaires,solids";
    view.height_px = 0;
    view.three_js = report::three_js_module();
    const std::string title = scene.name.empty() ? project_file.filename().string() : scene.name;
    report::write_text_file(out, report::scene_view_page(title, glb, view));
    if (view.three_js.empty())
      std::fprintf(stderr,
                   "luxgrid: warning: built without three.js: %s says the 3D view is not "
                   "available (write a .glb instead, or install three.js: "
                   "scripts/install-npm-tools.sh)\n",
                   out.string().c_str());
  }
  std::printf("scene written to %s\n", out.string().c_str());
  return 0;
}

}  // namespace luxgrid::cli
