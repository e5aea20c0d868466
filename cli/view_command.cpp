// `luxgrid view PROJECT [-o FILE]`: the project in 3D without calculating, to check the input
// (rooms, obstacles, luminaires with their C0 arrows and photometric solids, calculation
// surfaces): a page with the 3D view (FILE.html, the default `<project>.view.html` beside the
// project) or the scene as glTF (FILE.glb), as report.html and scene.glb show it (docs/report.md).
#include <cstdio>
#include <filesystem>

#include "cli/commands.h"
#include "project/project_file.h"
#include "report/embedded_scripts.h"
#include "report/luminaire_types.h"
#include "report/output_folder.h"
#include "report/scene_glb.h"
#include "report/scene_view_html.h"
#include "util/error.h"

namespace luxgrid::cli {

int run_view(const ViewArgs& args) {
  namespace fs = std::filesystem;
  const fs::path project_file = args.project;
  fs::path out = args.out;
  if (out.empty()) out = fs::path(project_file).replace_extension(".view.html");
  const std::string ext = out.extension().string();
  if (ext != ".html" && ext != ".htm" && ext != ".glb")
    throw InputError(out.string() + ": the file must end in .html or .glb");
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
