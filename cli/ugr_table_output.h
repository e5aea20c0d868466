#pragma once
// `luxgrid info FILE --ugr`: the CIE 190 UGR table (calc/glare/ugr_table.h) as data sheets print
// it, and as JSON.
#include <string>

#include <nlohmann/json.hpp>

#include "calc/glare/ugr_table.h"

namespace luxgrid::cli {

// Rows X x Y, columns crosswise then endwise for the five reflectance combinations; the values
// for the file's lamp flux (the 1000 lm table plus 8 log10(F / 1000)), one decimal.
std::string ugr_table_text(const calc::glare::UgrTable& t);

// {"method", "spacing_H", "lamp_flux_lm", "correction", "reflectances": [[c, w, f] x 5],
//  "rooms": [{"x_H", "y_H", "crosswise": [5], "endwise": [5], "crosswise_1000lm",
//  "endwise_1000lm"}]}
// (null where no luminaire lies in the field).
nlohmann::json ugr_table_json(const calc::glare::UgrTable& t);

}  // namespace luxgrid::cli
