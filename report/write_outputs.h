#pragma once
// Everything a calculation leaves in its output folder: results.json, <surface>.csv, for grid
// surfaces <surface>.png, scene.glb (with a scene), report.html (unless switched off) and, when
// asked for, <surface>.npy.
#include <optional>
#include <string>
#include <vector>

#include "calc/daylight/en17037.h"
#include "calc/results.h"
#include "calc/scene.h"
#include "report/colour_scale.h"
#include "report/diff.h"
#include "report/luminaire_types.h"
#include "report/output_folder.h"
#include "report/requirement_checks.h"

namespace luxgrid::report {

struct OutputOptions {
  bool report = true;       // report.html
  bool arrays_npy = false;  // <surface>.npy per surface (report/surface_npy.h)
  // <surface>_direct.png and <surface>_indirect.png beside each grid's plot, when reflected light
  // ran (--part-plots): two more plots a surface, asked for, not written by default.
  bool part_plots = false;
  std::optional<ColourScale> scale;      // one fixed scale for every surface; default: per surface
  const calc::Scene* scene = nullptr;    // luminaire marks, plan view and schedule; null: left out
  std::vector<RequirementCheck> checks;  // also written into results.json per surface
  // The luminaire types' data (report/luminaire_types.h) when known already (`luxgrid report`
  // reads them from results.json); null: worked out from `scene`'s photometry.
  const std::vector<LuminaireType>* types = nullptr;
  // results.json as it is to be written, when it exists already (`luxgrid report`: the file it
  // read); null: written from the results.
  const std::string* results_json = nullptr;
  const CostTable* cost = nullptr;  // the `luxgrid cost` table, into the report
  std::string version;              // luxgrid version for the report
  // The EN 17037 assessment (report/en17037_checks.h): results.json's `en17037`, the report's
  // table; null: none asked.
  const daylight::En17037Assessment* en17037 = nullptr;
};

// Writes into folder.staging(); adds the "report" phase to results.timing_s. Returns warnings.
std::vector<std::string> write_outputs(calc::Results& results, const OutputFolder& folder,
                                       const OutputOptions& options);
std::vector<std::string> write_outputs(calc::Results& results, const OutputFolder& folder);

}  // namespace luxgrid::report
