#pragma once
// Energy figures per room for the report: installed power, power density (W/m^2) and normalised
// power density (W/m^2 per 100 lx of maintained average illuminance on the room's reference
// surface): plain ratios of the installed power, the floor area and the calculated average, the
// figures designers compare installations by.
#include <optional>
#include <string>
#include <vector>

#include "calc/results.h"
#include "calc/scene.h"
#include "report/luminaire_types.h"
#include "report/requirement_checks.h"

namespace luxgrid::report {

struct RoomEnergy {
  std::string room;
  double area_m2 = 0.0;                    // floor area of the outline
  int luminaires = 0;                      // luminaires whose position lies over the outline
  std::optional<double> power_W;           // installed; none when a file gives no power
  std::vector<std::string> without_power;  // photometry entries whose file gives no power
  std::string reference_surface;           // the horizontal grid whose Eavg normalises; empty: none
  std::optional<double> Eavg_lx;

  std::optional<double> W_per_m2() const;
  std::optional<double> W_per_m2_per_100lx() const;
};

// The reference surface of a room is the first horizontal, upward-facing grid in it that carries
// an Em requirement, else the first such grid above the floor (a workplane), else its floor grid.
// The power each luminaire's file states comes from `types` (report/luminaire_types.h).
std::vector<RoomEnergy> room_energy(const calc::Scene& scene,
                                    const std::vector<LuminaireType>& types,
                                    const calc::Results& results,
                                    const std::vector<RequirementCheck>& checks);

}  // namespace luxgrid::report
