#pragma once
// scene.glb: the project in 3D with its results, as glTF 2.0 binary [glTF2] (docs/report.md,
// "scene.glb"). Metres, +y up as glTF requires: one root node, named after the project, turns
// luxgrid's frame (+z up) into glTF's, (x, y, z) -> (x, z, -y), and holds everything else in
// luxgrid's own coordinates. Rooms grey by reflectance with their daylight openings as holes,
// each opening a node of its room (glass a translucent pane, an unglazed opening its outline),
// obstacles, luminaires (opening, body, C0
// arrow, photometric solid), grid surfaces coloured by the colour scale at every vertex, points
// and observers as markers; node names are the project's names, values in each node's extras.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calc/results.h"
#include "calc/scene.h"
#include "report/colour_scale.h"
#include "report/luminaire_types.h"
#include "report/raster.h"

namespace luxgrid::report {

struct SceneGlbInput {
  // Rooms, obstacles, luminaires; and the surfaces, when there are no results.
  const calc::Scene* scene = nullptr;
  // The values; null: the scene's surfaces are drawn without values (`luxgrid view`).
  const calc::Results* results = nullptr;
  const std::vector<LuminaireType>* types = nullptr;  // their photometric solids; null: none
  std::optional<ColourScale> scale;                   // fixed (--scale); else scene_colour_scale's
  std::string version;                                // luxgrid's, for the asset's generator
};

std::string scene_glb(const SceneGlbInput& in);

// The colour scale of every grid surface in the 3D scene: one for all, so that colours compare
// across surfaces (the maps have one each): `fixed`, else fit_scale over every grid's values.
ColourScale scene_colour_scale(const calc::Results& results,
                               const std::optional<ColourScale>& fixed);

// An sRGB colour as glTF's linear values (COLOR_0 and material factors are linear), IEC
// 61966-2-1's transfer function.
Rgb srgb_to_linear(const Rgb& c);

// The root node's matrix, glTF's column-major order: luxgrid's (x, y, z) to glTF's (x, z, -y).
inline constexpr std::array<double, 16> kZUpToYUp = {1, 0, 0, 0, 0, 0, -1, 0,
                                                     0, 1, 0, 0, 0, 0, 0,  1};

// The length of the largest intensity of every photometric solid in the scene, m: a third of
// the highest room, 1 m without rooms.
double solid_length_m(const calc::Scene& scene);

}  // namespace luxgrid::report
