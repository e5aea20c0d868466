#include "report/luminaire_data.h"

namespace luxgrid::report {

namespace {

std::string first_of(const photometry::Photometry& p, std::initializer_list<const char*> keys) {
  for (const char* k : keys) {
    const auto it = p.keywords.find(k);
    if (it != p.keywords.end() && !it->second.empty()) return it->second;
  }
  return "";
}

}  // namespace

LuminaireData luminaire_data(const photometry::Photometry& p) {
  LuminaireData d;
  d.name = first_of(p, {"LUMINAIRE"});
  d.manufacturer = first_of(p, {"MANUFAC", "COMPANY"});
  d.article = first_of(p, {"LUMCAT"});
  double watts = 0.0;
  for (const auto& set : p.lamp_sets) watts += set.power_w > 0.0 ? set.power_w : 0.0;
  if (watts > 0.0) d.power_W = watts;
  return d;
}

}  // namespace luxgrid::report
