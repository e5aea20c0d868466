#pragma once
// What a photometric file says about the product, for the report's luminaire list: its name,
// manufacturer and article number (IES keywords [LUMINAIRE], [MANUFAC], [LUMCAT]; EULUMDAT lines
// 9, 1 and 10) and its electrical power (IES input watts; EULUMDAT's wattage of every lamp set,
// which includes the ballast) where the file gives one.
#include <optional>
#include <string>

#include "photometry/photometry.h"

namespace luxgrid::report {

struct LuminaireData {
  std::string name, manufacturer, article;  // empty where the file does not say
  std::optional<double> power_W;            // per luminaire; none when the file gives 0 or nothing
};

LuminaireData luminaire_data(const photometry::Photometry& p);

}  // namespace luxgrid::report
