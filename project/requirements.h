#pragma once
// What a project's surfaces must meet, EN 12464-1 style [EN12464-1], as read from the project.
// A calculation surface (a task area) may carry
//   "requirements": { "preset": "office-writing", "Em": 500, "U0": 0.6, "Emin": 300, "Emax": 1000,
//                     "UGR_L": 19, "Ra": 80, "Ez": 150, "Esc": 50, "modelling": [0.3, 0.6],
//                     "glare_observers": "eyes", "cylindrical": "faces", "horizontal": "faces h" }
// and a room_surfaces entry { "preset": "walls-and-ceilings", "walls": {"Em": 50, "U0": 0.1},
// "ceiling": {...}, "floor": {...} }. Em (maintained average illuminance, lx), U0 (Emin / Eavg),
// Emin, Ez, Esc and Ra are lower limits; Emax and UGR_L upper limits; modelling a range. A value
// exactly at the limit meets it. docs/compliance.md is the user's reference.
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "project/json_reader.h"

namespace luxgrid::project {

// What one grid must meet.
struct SurfaceRequirements {
  std::string role = "task area";        // "task area", "wall", "ceiling", "floor"
  std::map<std::string, double> limits;  // "Em", "U0", "Emin", "Emax", "Ez", "Esc", "UGR_L", "Ra"
  // The quantities a preset filled (an explicit key overrides the preset and is not listed), with
  // the row's citation: "office-writing: EN 12464-1:2021 Table 5.26 Offices, ref. 5.26.2".
  std::map<std::string, std::string> from_preset;
  std::optional<std::pair<double, double>> modelling;  // Ez / Eh at every point within [lo, hi]
  std::string preset;                                  // the preset key, or empty
  std::vector<std::string> glare_observers;  // observers surfaces for UGR_L; empty: every one
  std::string cylindrical;  // the cylindrical surface giving Ez (and modelling's numerator)
  std::string horizontal;   // on a cylindrical surface: the horizontal one giving modelling's Eh
};

struct Requirements {
  std::map<std::string, SurfaceRequirements> surfaces;  // by grid name ("room ceiling" included)
  // room_surfaces entry name -> what each of its "<name> wall k" grids must meet.
  std::map<std::string, SurfaceRequirements> walls;
  bool empty() const { return surfaces.empty() && walls.empty(); }
};

// Reads `req`, the "requirements" of the /surfaces entry `surface` (`surfaces` is the whole
// array, for the surfaces a requirement names), into `out`. Every key of `req` is read or refused
// here. Throws InputError naming the file and JSON pointer: an unknown quantity
// (`p.json /surfaces/0/requirements/Eav: unknown quantity "Eav", expected ...`), a value that
// is not a positive number, U0 above 1, an unknown preset, a quantity the surface does not
// compute (Ez on a planar surface that names no cylindrical one), a named surface that does not
// exist or computes the wrong quantity.
void parse_requirements(const JsonValue& req, const JsonValue& surface, const JsonValue& surfaces,
                        Requirements& out);

// The same for every entry of /surfaces of a raw project document, `label` naming it (the
// loader reads requirements with the rest of the project: project/project_file.h).
Requirements parse_requirements(const nlohmann::json& project, const std::string& label);

}  // namespace luxgrid::project
