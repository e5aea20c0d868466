#pragma once
// The standard UGR table of a luminaire, CIE 190's tabular method [CIE190] on CIE 117's formula
// [CIE117] (docs/glare.md): an observer at eye level at the middle of one wall of an empty
// X x Y room looks along Y, horizontally; the luminaires fill the ceiling plane H above the eye
// on a square grid of spacing S = 0.25 H (the first row and column S/2 from the walls), their
// C0-C180 plane along the line of sight ("crosswise") or across it ("endwise"). Each room's
// UGR sums the luminaires in the Guth field (glare_term); the background luminance is the
// walls' mean indirect illuminance over pi, from a three-surface flux transfer
// (flux_transfer.h) of the luminaires' direct flux onto the floor (the plane at eye level),
// walls and ceiling. The table is for the distribution scaled to 1000 lm of lamp flux; a
// luminaire of lamp flux F adds 8 log10(F / 1000).
#include <array>
#include <optional>
#include <vector>

#include "photometry/photometry.h"

namespace luxgrid::calc::glare {

// The standard's rows: room X x Y in multiples of H (X across the line of sight, Y along it).
struct TableRoom {
  double x_H, y_H;
};
inline constexpr std::array<TableRoom, 19> kTableRooms = {{{2, 2},
                                                           {2, 3},
                                                           {2, 4},
                                                           {2, 6},
                                                           {2, 8},
                                                           {2, 12},
                                                           {4, 2},
                                                           {4, 3},
                                                           {4, 4},
                                                           {4, 6},
                                                           {4, 8},
                                                           {4, 12},
                                                           {8, 4},
                                                           {8, 6},
                                                           {8, 8},
                                                           {8, 12},
                                                           {12, 4},
                                                           {12, 6},
                                                           {12, 8}}};
// The standard's reflectance combinations.
struct TableReflectances {
  double ceiling, walls, floor;
};
inline constexpr std::array<TableReflectances, 5> kTableReflectances = {
    {{0.7, 0.5, 0.2}, {0.7, 0.3, 0.2}, {0.5, 0.5, 0.2}, {0.5, 0.3, 0.2}, {0.3, 0.3, 0.2}}};
inline constexpr double kTableSpacingOverH = 0.25;  // S / H
inline constexpr double kTableH_m = 2.0;  // luminaires above the eye (the UGR does not depend on it
                                          // for a luminaire small against H; docs/glare.md)
inline constexpr double kTableFluxLm = 1000.0;  // the table's lamp flux

enum class Viewing { crosswise, endwise };

// UGR of one room and reflectance combination for `distribution` as given (no flux scaling);
// none when no luminaire lies in the Guth field. The opening must have an area.
std::optional<double> table_ugr(const photometry::IntensityDistribution& distribution,
                                const photometry::LuminousOpening& opening, const TableRoom& room,
                                const TableReflectances& reflectance, Viewing viewing);

// Both viewings of one room: the same values as two table_ugr calls, for half the lookups.
struct TableUgrs {
  std::optional<double> crosswise, endwise;
};
TableUgrs table_ugrs(const photometry::IntensityDistribution& distribution,
                     const photometry::LuminousOpening& opening, const TableRoom& room,
                     const TableReflectances& reflectance);

struct UgrTable {
  double lamp_flux_lm = 0.0;  // F: stated lamp flux, or the luminaire flux for absolute photometry
  double correction = 0.0;    // 8 log10(F / 1000)
  // [room][reflectance] at 1000 lm of lamp flux.
  std::vector<std::array<std::optional<double>, 5>> crosswise, endwise;
};

// The whole table for `distribution` (absolute cd, lamp flux `lamp_flux_lm`). Throws InputError
// for an opening without area (UGR needs the luminous area) or a flux that is not positive.
UgrTable ugr_table(const photometry::DistributionPtr& distribution,
                   const photometry::LuminousOpening& opening, double lamp_flux_lm);

// The lamp flux a table is normalised by: the file's stated lamp flux, or the integrated
// luminaire flux for absolute photometry (LED files: lamp = luminaire).
double table_lamp_flux_lm(const photometry::Photometry& p,
                          const photometry::IntensityDistribution& distribution);

}  // namespace luxgrid::calc::glare
