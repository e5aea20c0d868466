#pragma once
// The 3D view (docs/report.md, "The 3D view"): report.html's section with the element `scene-3d`,
// and the page of `luxgrid view`. Both embed scene.glb (base64), three.js and the view's script
// (report/embedded_scripts.h), so they work offline and from file://. A luxgrid built without
// three.js writes the section with a sentence that says the view is not available.
#include <string>
#include <string_view>

#include "report/html_report.h"

namespace luxgrid::report {

// What the view shows when the page opens: the layers checked, among rooms, surfaces,
// luminaires, solids (the photometric solids).
struct SceneViewOptions {
  std::string show = "rooms,surfaces,luminaires";
  int height_px = 460;  // the canvas's height; 0: the whole window (the page of `luxgrid view`)
  std::string_view three_js;  // three.js's module; empty: the view is not available
};

// The section (heading, the view, its caption and scripts), to `put`.
void scene_view_section(const std::string& glb, const SceneViewOptions& options,
                        const TextSink& put);

// The tag at the head of every page scene_view_page writes: `luxgrid view` overwrites an existing
// file only when it holds this tag (or is a luxgrid glb), never a file of the user's.
inline constexpr const char* kViewPageTag = "<meta name=\"generator\" content=\"luxgrid view\">";

// A page of its own: the title and the view filling the window (`luxgrid view`).
std::string scene_view_page(const std::string& title, const std::string& glb,
                            const SceneViewOptions& options);

// The style the view needs, for the page's style sheet.
std::string scene_view_style();

}  // namespace luxgrid::report
