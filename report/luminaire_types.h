#pragma once
// What the report says of each photometry entry (its row in the luminaire table and its polar
// diagram), worked out from the scene before the page is written: the product data and power the
// file states, the flux as used, the light output ratio, CIE 190's tabular UGR and the polar
// curves and the photometric solid the 3D views draw. results.json keeps them
// (docs/project-format.md), so `luxgrid report` needs no photometric file.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "calc/scene.h"
#include "report/photometric_solid.h"
#include "report/polar_diagram.h"

namespace luxgrid::report {

struct LuminaireType {
  std::string key;                          // the photometry entry
  std::string name, manufacturer, article;  // as the file names them; empty where it does not
  std::string format;                       // "IES LM-63-2002", "EULUMDAT", "builtin", ...
  std::string file;                         // the photometric file's name
  int count = 0;                            // luminaires using it
  std::optional<double> flux_lm;            // each, as used (the project's flux_lm or multiplier)
  std::optional<double> power_W;            // each, as the file states it
  std::optional<double> lor;                // light output ratio
  // CIE 190's 4H x 8H value at reflectances 0.7 / 0.5 / 0.2, crosswise and endwise, for the
  // luminaire as used (none for a point opening or where the table gives no value).
  std::optional<double> ugr_crosswise, ugr_endwise;
  std::optional<PolarCurves> polar;       // none without a distribution
  std::optional<PhotometricSolid> solid;  // for the 3D views; none without a distribution
};

// One per photometry entry, in the scene's order. `known_flux_lm`: the luminous flux of
// distributions the calculation integrated already (calc::luminous_flux, by distribution), so
// they are not integrated again.
std::vector<LuminaireType> luminaire_types(
    const calc::Scene& scene,
    const std::map<const photometry::IntensityDistribution*, double>& known_flux_lm = {});

}  // namespace luxgrid::report
