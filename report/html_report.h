#pragma once
// report.html: the one self-contained page a lighting designer hands over. Images are inline
// (PNG as base64 data URIs, plan views and polar diagrams as inline SVG), the one script is the
// 3D view's (embedded, three.js included), there is no external resource, and a print style sheet
// lays it out on A4.
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "calc/daylight/en17037.h"
#include "calc/results.h"
#include "calc/scene.h"
#include "report/diff.h"
#include "report/embedded_scripts.h"
#include "report/energy.h"
#include "report/html_text.h"
#include "report/luminaire_types.h"
#include "report/requirement_checks.h"
#include "report/room_figures.h"

namespace luxgrid::report {

struct ReportInput {
  const calc::Results* results = nullptr;
  const calc::Scene* scene = nullptr;  // null: no plan view, no luminaire schedule
  // Worked out before the page (luminaire_types, room_energy, room_figures): the page only
  // presents them.
  std::vector<LuminaireType> types;        // one per photometry entry
  std::vector<RoomEnergy> energy;          // per room
  std::vector<RoomFigures> rooms;          // per room of *scene, in its order
  std::map<std::string, std::string> png;  // surface name -> PNG file bytes (the maps)
  std::vector<RequirementCheck> checks;
  const CostTable* cost = nullptr;  // --with-cost
  std::string version;              // "0.1.0"
  std::string date;                 // "2024-05-01 14:03 UTC"
  // luminaire_sections_html(types, *scene) when the caller made it already (write_outputs makes it
  // while the plots are drawn); empty: html_report makes it.
  std::string luminaires_html;
  // scene.glb's bytes, for the 3D view (report/scene_view_html.h); null: no 3D view.
  const std::string* scene_glb = nullptr;
  // three.js for the 3D view (report/embedded_scripts.h); empty: the page says the view is not
  // available.
  std::string_view three_js = three_js_module();
  // The EN 17037 assessment (report/en17037_html.h: its table after the compliance table); null:
  // none asked.
  const daylight::En17037Assessment* en17037 = nullptr;
};

// Where the page's text goes, piece by piece and in order.
using TextSink = std::function<void(std::string_view)>;

// The page, handed to `put` as it is made: the images' base64 a few kilobytes at a time, so
// that a report with a megabyte of images is never a megabyte of text in memory.
void write_html_report(const ReportInput& in, const TextSink& put);
// The same page as one string.
std::string html_report(const ReportInput& in);

// The report's luminaire types (product data, flux, power, LOR, CIE 190 UGR, polar diagrams) and
// positions: the part of the page that draws the most (the polar diagrams), so it can be made
// beforehand.
std::string luminaire_sections_html(const std::vector<LuminaireType>& types,
                                    const calc::Scene& scene);

// RFC 4648 base64 of `bytes`: to `put` in pieces, or as one string.
void base64_to(std::string_view bytes, const TextSink& put);
std::string base64(std::string_view bytes);

// The numbers as the report prints them (tests compare the page with results.json through these).
std::string format_lux_value(double lx);       // "%.1f"
std::string format_ratio_value(double ratio);  // "%.3f"

}  // namespace luxgrid::report
