// `luxgrid info FILE [--json] [--at C,gamma ...] [--plot out.png] [--interpolation bicubic]
// [--ugr]`: what a photometric file says and what luxgrid derives from it, as text or JSON, and a
// polar (goniometric) diagram of the C0-C180 and C90-C270 planes drawn the way data sheets draw
// them: nadir at the bottom, C0 to the right and C180 to the left (solid), C90 right / C270 left
// (dashed), intensity rings at round values.
//
// --at angles: for type C files the file's own C numbering (C0 = +x, counter-clockwise from
// above) and gamma from nadir; for types A and B, luxgrid's frame after the mapping documented in
// photometry/symmetry.h (and docs/photometry.md).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "calc/glare/ugr_table.h"
#include "cli/commands.h"
#include "cli/photometry_info.h"
#include "cli/ugr_table_output.h"
#include "photometry/derived_photometry.h"
#include "photometry/photometry.h"
#include "photometry/source_text.h"
#include "photometry/tabular_distribution.h"
#include "photometry/tilt.h"
#include "report/png_file.h"
#include "report/polar_diagram.h"
#include "util/error.h"

namespace luxgrid::cli {

namespace {

using namespace luxgrid::photometry;

using At = InfoAt;

At parse_at(const std::string& s) {
  const auto comma = s.find(',');
  double c = 0, g = 0;
  if (comma == std::string::npos ||
      !try_parse_number(trim(std::string_view(s).substr(0, comma)), c) ||
      !try_parse_number(trim(std::string_view(s).substr(comma + 1)), g))
    throw InputError("--at '" + s + "': expected C,gamma in degrees, e.g. --at 0,30");
  if (g < 0 || g > 180)
    throw InputError("--at '" + s + "': expected gamma between 0 and 180 degrees");
  return {c, g};
}

void write_polar_png(const Photometry& p, const std::string& title,
                     const std::filesystem::path& path) {
  // Without the font the diagram is still drawn, just unlabelled.
  const report::Raster img = report::polar_diagram(*p.distribution, title, 640);
  // Written beside the target and renamed, so no partial image is ever left behind.
  const std::filesystem::path tmp =
      path.parent_path() / (path.stem().string() + ".partial" + path.extension().string());
  try {
    report::write_png(img, tmp);
  } catch (const CalculationError& e) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw InputError(e.what());
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec)
    throw InputError(SourceLocation{path.string()}, "cannot write the image: " + ec.message());
}

}  // namespace

int run_info(const InfoArgs& args) {
  const std::string& file = args.file;
  const bool json = args.json;
  const std::string& plot = args.plot;
  const std::string& interpolation = args.interpolation;
  const bool ugr = args.ugr;
  const std::vector<std::string>& at_args = args.at;
  std::vector<At> at;
  for (const auto& s : at_args) at.push_back(parse_at(s));
  const PhotometryInfo info = read_photometry_info(file, at, interpolation, ugr);
  const Photometry& p = info.photometry;
  const DerivedPhotometry& d = info.derived;
  const auto& ugr_table = info.ugr_table;
  const auto& intensities = info.intensity_cd;
  if (json) {
    const nlohmann::json j = photometry_info_json(info);
    std::printf("%s\n", j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
  } else {
    std::printf("%s\n", p.source.c_str());
    std::printf("  format        %s (type %s, symmetry %s, %d x %d angles)\n", p.format.c_str(),
                to_string(p.photometric_type), to_string(p.symmetry), p.counts_vertical,
                p.counts_horizontal);
    for (const char* k :
         {"MANUFAC", "LUMCAT", "LUMINAIRE", "LAMP", "TEST", "COMPANY", "REPORT", "DATE"})
      if (auto it = p.keywords.find(k); it != p.keywords.end()) {
        std::string v = it->second;
        for (char& ch : v)
          if (ch == '\n') ch = ' ';
        std::printf("  %-13s %s\n", k, v.c_str());
      }
    for (const auto& l : p.lamp_sets)
      std::printf("  lamps         %d x %s, %.1f lm, %.1f W%s\n", l.count,
                  l.type.empty() ? "-" : l.type.c_str(), l.flux_lm, l.power_w,
                  l.count < 0 ? " (absolute photometry)" : "");
    if (p.lamp_flux_lm)
      std::printf("  lamp flux     %.1f lm (stated)\n", *p.lamp_flux_lm);
    else
      std::printf("  lamp flux     - (absolute photometry)\n");
    if (!p.flux_convention.empty()) std::printf("  photometry    %s\n", p.flux_convention.c_str());
    std::printf("  flux          %.1f lm (integrated, %s)\n", d.flux_lm,
                p.table ? to_string(p.table->interpolation()) : "-");
    if (d.lor)
      std::printf("  LOR           %.4f%s\n", *d.lor,
                  p.stated_lor ? (" (stated " + format_number(*p.stated_lor) + ")").c_str() : "");
    std::printf("  DFF           %.4f%s\n", d.dff,
                p.stated_dff ? (" (stated " + format_number(*p.stated_dff) + ")").c_str() : "");
    std::printf("  max           %.1f cd at C %.1f, gamma %.1f deg\n", d.max_cd, d.max_c_deg,
                d.max_gamma_deg);
    std::printf("  beam / field  C0-C180 %.1f / %.1f deg, C90-C270 %.1f / %.1f deg\n",
                d.c0_c180.beam_deg, d.c0_c180.field_deg, d.c90_c270.beam_deg, d.c90_c270.field_deg);
    std::printf("  opening       %s, %.4g x %.4g m (length along C0 x width), height %.4g m\n",
                p.opening.description.c_str(), p.opening.length, p.opening.width, p.opening.height);
    for (std::size_t k = 0; k < at.size(); ++k)
      std::printf("  I(C %g, gamma %g) = %.6g cd\n", at[k].c_deg, at[k].gamma_deg, intensities[k]);
    if (ugr_table) std::printf("\n%s", ugr_table_text(*ugr_table).c_str());
  }
  // On stderr, as every command prints its warnings (--json keeps them in its "warnings" too).
  for (const auto& w : p.warnings) std::fprintf(stderr, "luxgrid: warning: %s\n", w.c_str());
  if (!plot.empty()) write_polar_png(p, std::filesystem::path(file).filename().string(), plot);
  return 0;
}

}  // namespace luxgrid::cli
