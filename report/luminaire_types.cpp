#include "report/luminaire_types.h"

#include <filesystem>

#include "calc/glare/ugr_table.h"
#include "calc/scaled_distribution.h"
#include "photometry/derived_photometry.h"
#include "report/luminaire_data.h"

namespace luxgrid::report {

std::vector<LuminaireType> luminaire_types(
    const calc::Scene& scene,
    const std::map<const photometry::IntensityDistribution*, double>& known_flux_lm) {
  std::vector<LuminaireType> types;
  for (const auto& [key, p] : scene.photometry) {
    LuminaireType t;
    t.key = key;
    const calc::Luminaire* first = nullptr;
    for (const auto& l : scene.luminaires) {
      if (l.photometry != key) continue;
      ++t.count;
      if (!first) first = &l;
    }
    // As used: a project flux_lm or multiplier applied, and the project's "emitter", if any.
    const photometry::IntensityDistribution* dist =
        first && first->distribution ? first->distribution.get() : p.distribution.get();
    const photometry::LuminousOpening* opening = first ? &first->opening : &p.opening;
    const LuminaireData file = luminaire_data(p);
    t.name = file.name;
    t.manufacturer = file.manufacturer;
    t.article = file.article;
    t.power_W = file.power_W;
    t.format = p.format;
    t.file = std::filesystem::path(p.source).filename().string();
    if (dist) {
      const auto known = known_flux_lm.find(dist);
      t.flux_lm = known != known_flux_lm.end() ? known->second : calc::luminous_flux(*dist);
    }
    const auto d = photometry::derive(p);
    t.lor = d.lor ? d.lor : p.stated_lor;
    // The 1000 lm table plus 8 log10(F / 1000) is the UGR of the distribution itself.
    if (dist && opening->shape != photometry::LuminousOpening::Shape::point) {
      const calc::glare::TableRoom room{4, 8};
      const auto [c, e] =
          calc::glare::table_ugrs(*dist, *opening, room, calc::glare::kTableReflectances[0]);
      t.ugr_crosswise = c;
      t.ugr_endwise = e;
    }
    if (dist) t.polar = polar_curves(*dist);
    if (dist) t.solid = photometric_solid(*dist);
    types.push_back(std::move(t));
  }
  return types;
}

}  // namespace luxgrid::report
