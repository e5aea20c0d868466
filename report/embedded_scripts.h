#pragma once
// The scripts report.html's 3D view embeds (report/scene_view_html.h), built into the binary by
// cmake/embed_scripts.cmake, so a report works offline and from file:// with nothing beside it.
#include <string_view>

namespace luxgrid::report {

// report/scene_view.js: builds the view from the page's scene.glb.
std::string_view scene_view_script();
// three.js's ES module build (three.module.min.js of the npm package `three`, the version of
// scripts/npm/package-lock.json); empty when luxgrid was built without it.
std::string_view three_js_module();
std::string_view three_js_version();  // "r170"; empty without it

}  // namespace luxgrid::report
