#include "cli/photometry_info.h"

#include <filesystem>

#include "cli/ugr_table_output.h"
#include "photometry/source_text.h"
#include "photometry/tabular_distribution.h"
#include "photometry/tilt.h"
#include "util/error.h"

namespace luxgrid::cli {

namespace {

using namespace luxgrid::photometry;

const char* shape_name(LuminousOpening::Shape s) {
  switch (s) {
    case LuminousOpening::Shape::point: return "point";
    case LuminousOpening::Shape::rectangle: return "rectangle";
    case LuminousOpening::Shape::disk: return "disk";
  }
  return "?";
}

nlohmann::json optional_number(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

}  // namespace

PhotometryInfo read_photometry_info(const std::string& file, const std::vector<InfoAt>& at,
                                    const std::string& interpolation, bool ugr) {
  // A TILT file named by FILE must lie in FILE's folder or below it (docs/photometry.md).
  LoadOptions options;
  options.allowed_root = std::filesystem::absolute(file).parent_path();
  Photometry p = load_photometry_file(file, options);
  if (interpolation == "bicubic" && p.table) {
    p.table = p.table->with_interpolation(Interpolation::bicubic);
    p.distribution = p.table;
  }
  const DerivedPhotometry d = derive(p);
  std::optional<calc::glare::UgrTable> ugr_table;
  if (ugr) {
    // The reader's place in front of the table's message (a file without luminous area).
    try {
      ugr_table = calc::glare::ugr_table(p.distribution, p.opening,
                                         calc::glare::table_lamp_flux_lm(p, *p.distribution));
    } catch (const InputError& e) {
      throw InputError(SourceLocation{file}, e.what());
    }
  }
  std::vector<double> intensities;
  for (const InfoAt& x : at)
    intensities.push_back(
        p.distribution->intensity(direction_of(x.c_deg * kDegToRad, x.gamma_deg * kDegToRad)));
  return {std::move(p), d, std::move(ugr_table), at, std::move(intensities)};
}

nlohmann::json photometry_info_json(const PhotometryInfo& info) {
  const Photometry& p = info.photometry;
  const DerivedPhotometry& d = info.derived;
  const auto& at = info.at;
  const auto& intensities = info.intensity_cd;
  const auto& ugr_table = info.ugr_table;
  nlohmann::json j;
  j["source"] = p.source;
  j["format"] = p.format;
  j["version"] = p.version;
  j["photometric_type"] = to_string(p.photometric_type);
  j["symmetry"] = to_string(p.symmetry);
  j["interpolation"] = p.table ? to_string(p.table->interpolation()) : "none";
  j["counts"] = {{"vertical", p.counts_vertical}, {"horizontal", p.counts_horizontal}};
  j["flux_lm"] = d.flux_lm;
  j["downward_flux_lm"] = d.downward_flux_lm;
  j["lamp_flux_lm"] = optional_number(p.lamp_flux_lm);
  j["flux_convention"] = p.flux_convention;
  j["lor"] = optional_number(d.lor);
  j["dff"] = d.dff;
  j["stated_lor"] = optional_number(p.stated_lor);
  j["stated_dff"] = optional_number(p.stated_dff);
  j["candela_multiplier"] = p.candela_multiplier;
  j["max_cd"] = d.max_cd;
  j["max_direction"] = {{"c_deg", d.max_c_deg}, {"gamma_deg", d.max_gamma_deg}};
  j["beam"] = {
      {"c0_c180", {{"beam_deg", d.c0_c180.beam_deg}, {"field_deg", d.c0_c180.field_deg}}},
      {"c90_c270", {{"beam_deg", d.c90_c270.beam_deg}, {"field_deg", d.c90_c270.field_deg}}}};
  j["opening"] = {{"shape", shape_name(p.opening.shape)},
                  {"description", p.opening.description},
                  {"length_m", p.opening.length},
                  {"width_m", p.opening.width},
                  {"height_m", p.opening.height}};
  nlohmann::json lamps = nlohmann::json::array();
  for (const auto& l : p.lamp_sets)
    lamps.push_back({{"count", l.count},
                     {"type", l.type},
                     {"flux_lm", l.flux_lm},
                     {"colour", l.colour},
                     {"cri", l.cri},
                     {"power_w", l.power_w}});
  j["lamps"] = lamps;
  j["keywords"] = p.keywords;
  j["warnings"] = p.warnings;
  j["at"] = nlohmann::json::array();
  for (const InfoAt& x : at) j["at"].push_back({x.c_deg, x.gamma_deg});
  j["intensity_cd"] = intensities;
  if (ugr_table) j["ugr_table"] = ugr_table_json(*ugr_table);
  if (p.tilt)
    j["tilt"] = {{"geometry", p.tilt->lamp_to_luminaire_geometry},
                 {"angles_deg", p.tilt->angle_deg},
                 {"factors", p.tilt->factor}};
  return j;
}

}  // namespace luxgrid::cli
