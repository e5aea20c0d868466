#pragma once
// The colour rendering index Ra of the lamps a project uses, as their photometric files state it:
// EULUMDAT's lamp-set field "colour rendering group / index" (a number such as 80 or 82, "Ra80",
// ">80", or a CIE group 1A / 1B / 2A / 2B / 3 / 4) and, for IES files, a keyword [_CRI], [CRI] or
// [RA]. A group gives its lower bound (1A: Ra >= 90, 1B: 80, 2A: 70, 2B: 60, 3: 40, 4: 20
// [CIE29.2]); what is neither stays unknown.
#include <optional>
#include <string>

#include "calc/scene.h"
#include "photometry/photometry.h"

namespace luxgrid::report {

// The Ra a text states, or none: "80" -> 80, "Ra 82" -> 82, ">=80" -> 80, "1B" -> 80, "Unknown" ->
// none.
std::optional<double> parse_colour_rendering(const std::string& text);

// The lowest Ra over the file's lamp sets and keywords; none when no field states one.
std::optional<double> photometry_colour_rendering(const photometry::Photometry& p);

struct SceneColourRendering {
  std::optional<double>
      Ra;  // the lowest over every photometry entry the luminaires use; none if any is unknown
  std::string source;  // "photometry \"mirel\": Ra 80", or why it is unknown
};

// What the luminaires of `scene` give; a scene without luminaires gives none.
SceneColourRendering scene_colour_rendering(const calc::Scene& scene);

}  // namespace luxgrid::report
