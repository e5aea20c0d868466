// The first bounce through the intensity texture (calc/intensity_lookup.h): the flux each patch
// receives moves by no more than the texture's measured bound allows, and the texture is what
// the pieces look up (the fluxes do change).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "calc/indirect/first_bounce.h"
#include "calc/indirect/patches.h"
#include "calc/intensity_lookup.h"
#include "photometry/tabular_distribution.h"
#include "project/project_file.h"

namespace luxgrid::calc::indirect {
namespace {

TEST(FirstBounceLookup, TextureMovesPatchFluxWithinItsBound) {
  const auto doc = nlohmann::json::parse(R"({
    "format": "luxgrid-project/1", "name": "box",
    "settings": {"quality": "draft"},
    "photometry": { "mirel": "photometry/zumtobel_mirel_isym4.ldt" },
    "rooms": [ { "name": "r", "outline": [[0,0],[6,0],[6,4],[0,4]], "height": 3 } ],
    "luminaires": [ { "photometry": "mirel", "array": {"origin": [1.5, 1, 3], "count": [2, 2], "spacing": [3, 2]} } ],
    "surfaces": [ { "name": "p", "points": [ {"at": [3, 2, 0.8], "normal": [0, 0, 1]} ] } ]
  })");
  const Scene scene =
      project::parse_project(doc, "p.json",
                             std::filesystem::path(LUXGRID_SOURCE_DIR) / "examples/openplan")
          .scene;
  // The per-distribution choice (a scene this small gets the table from
  // choose_intensity_lookups: too few pairs for a texture to pay).
  const IntensityLookup chosen =
      choose_intensity_lookup(scene.luminaires[0].distribution, Quality::draft);
  ASSERT_NE(chosen.texture, nullptr);  // draft takes it
  // The bound of the texture draft took, measured in full (draft states only the probe's).
  const photometry::IntensityDistribution& table = *scene.luminaires[0].distribution;
  const double bound = texture_deviation(*chosen.texture, table).bound;
  std::map<const photometry::IntensityDistribution*, photometry::DistributionPtr> lookup;
  for (const auto& lum : scene.luminaires) lookup.emplace(lum.distribution.get(), chosen.lookup);

  const PatchMesh mesh = build_patch_mesh(scene, 0.5);
  const std::vector<const geometry::Visibility*> none(1, nullptr);
  const FirstBounce with_table = first_bounce(scene, mesh, none);
  const FirstBounce with_texture = first_bounce(scene, mesh, none, 0.08, nullptr, &lookup);
  // Each patch's flux is a sum of I x solid angle over its pieces, and each I moves by at most
  // bound x max(I, 1 % of I_max): the whole received flux by at most bound x (1 + 1 % of
  // I_max x 4 pi / flux), the floor's share spread over the sphere.
  const auto* tab = dynamic_cast<const photometry::TabularDistribution*>(&table);
  ASSERT_NE(tab, nullptr);
  const double i_max = *std::max_element(tab->grid().cd.begin(), tab->grid().cd.end());
  const double flux = with_table.received_flux_lm;
  EXPECT_LE(std::abs(with_texture.received_flux_lm - flux),
            bound * (flux + 0.01 * i_max * 4.0 * kPi * 4.0))  // four luminaires
      << "bound " << bound;
  std::printf(
      "[ first bounce through the texture ] received %.6g lm against %.6g lm (%+.4f %%), "
      "bound %.3g\n",
      with_texture.received_flux_lm, flux, 100.0 * (with_texture.received_flux_lm / flux - 1.0),
      bound);
  double moved = 0.0;
  for (size_t i = 0; i < mesh.patches.size(); ++i)
    moved = std::max(moved,
                     std::abs(with_texture.incident_flux_lm[i] - with_table.incident_flux_lm[i]));
  EXPECT_GT(moved, 0.0);  // the pieces did look the texture up
}

}  // namespace
}  // namespace luxgrid::calc::indirect
