#include "report/scene_view_html.h"

#include "report/embedded_scripts.h"
#include "report/html_text.h"

namespace luxgrid::report {

std::string scene_view_style() {
  return R"(.scene-3d { position: relative; border: 1px solid #bbb; background: #f4f4f4; }
.scene-3d canvas { display: block; width: 100%; height: var(--scene-3d-height); touch-action: none; }
.scene-3d-controls { position: absolute; left: 6px; top: 6px; background: rgba(255,255,255,.85);
  padding: 3px 6px; font-size: 9pt; border-radius: 3px; } .scene-3d-controls label { margin-right: .6em; }
.scene-3d-none { display: none; }
.scene-3d-legend { position: absolute; right: 10px; top: 10px; bottom: 40px; width: 64px; font-size: 8pt;
  text-align: center; } .scene-3d-bar { position: absolute; left: 4px; top: 18px; bottom: 0; width: 16px;
  border: 1px solid #555; } .scene-3d-bar span { position: absolute; left: 22px; transform: translateY(50%);
  white-space: nowrap; } .scene-3d-legend > div:last-child { position: absolute; top: 0; left: 4px; }
.scene-3d-info { margin: 0; padding: 4px 6px; font-size: 9pt; background: #fff; border-top: 1px solid #ddd;
  min-height: 1.3em; } .scene-3d.unavailable { padding: 1em; }
body.scene-3d-alone { margin: 0; padding: 0; max-width: none; } body.scene-3d-alone > :not(#scene-3d) { display: none; }
@media print { .scene-3d-controls, .scene-3d-info { display: none; } .scene-3d { break-inside: avoid; } }
)";
}

void scene_view_section(const std::string& glb, const SceneViewOptions& options,
                        const TextSink& put) {
  const std::string height = options.height_px > 0 ? std::to_string(options.height_px) + "px"
                                                   : std::string("calc(100vh - 2em)");
  if (options.three_js.empty()) {
    put("<div id=\"scene-3d\" class=\"scene-3d unavailable\" data-state=\"unavailable\"><p><strong>"
        "The 3D view is not available:</strong> this luxgrid was built without three.js "
        "(scripts/install-npm-tools.sh installs it; docs/report.md). The same scene is in "
        "scene.glb beside this report, for any glTF viewer.</p></div>\n");
    return;
  }
  put("<div id=\"scene-3d\" class=\"scene-3d\" data-state=\"loading\" data-show=\"" +
      html_escape(options.show) + "\" style=\"--scene-3d-height: " + height +
      "\"><canvas></canvas>"
      "<div class=\"scene-3d-controls\">"
      "<label><input type=\"checkbox\" data-layer=\"rooms\"> Rooms</label>"
      "<label><input type=\"checkbox\" data-layer=\"surfaces\"> Surfaces</label>"
      "<label><input type=\"checkbox\" data-layer=\"luminaires\"> Luminaires</label>"
      "<label><input type=\"checkbox\" data-layer=\"solids\"> Photometric solids</label>"
      "<button type=\"button\" data-home>Reset view</button></div>"
      "<div class=\"scene-3d-legend\"></div>"
      "<p class=\"scene-3d-info\">Drag: turn; right-drag or shift-drag: move; wheel: zoom; "
      "click a surface for its value.</p></div>\n");
  put("<script type=\"application/octet-stream\" id=\"scene-3d-glb\">");
  base64_to(glb, put);
  put("</script>\n<script type=\"text/plain\" id=\"scene-3d-three\">");
  put(options.three_js);
  put("</script>\n<script type=\"module\">");
  put(scene_view_script());
  put("</script>\n");
}

std::string scene_view_page(const std::string& title, const std::string& glb,
                            const SceneViewOptions& options) {
  std::string page =
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">" +
      std::string(kViewPageTag) +
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"><title>" +
      html_escape(title) +
      " - 3D view</title><style>body { margin: 0; font-family: " + kReportFontFamily +
      "; } .scene-3d { border: 0; }\n" + scene_view_style() + "</style></head><body>\n";
  scene_view_section(glb, options, [&](std::string_view s) { page += s; });
  return page + "</body></html>\n";
}

}  // namespace luxgrid::report
