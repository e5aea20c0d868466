#pragma once
// Warnings on intensity tables that read but cannot be what the maker meant (legal but
// suspicious input: Photometry::warnings, each naming the file, docs/photometry.md "Warnings"):
//
//  (a) every intensity is 0: the luminaire sends no light at all, which a project then
//      calculates as 0 lx without a word;
//  (b) a type C table that stops short of a pole (gamma 0 or 180) with intensities at its edge
//      that are not near zero: luxgrid sends nothing beyond the table, so the light is cut off
//      abruptly there. At gamma 90 that is a cut-off at the horizon (a downlight measured 0..90,
//      an uplight 90..180, as LM-63 and EULUMDAT allow); elsewhere (a table from gamma 20, or up
//      to 120) a dark cone under or above the luminaire that no measurement shows;
//  (c) luminous sizes whose sign the file's format gives no meaning: EULUMDAT sizes below 0
//      (0 is its circle), and in an LM-63-2002 or later file the LM-63-1995 rule "negative
//      width, length 0: round", which LM-63-2002 Table 1 no longer lists (opening.h reads it as
//      round for every version and warns on the combinations no version defines).
#include <string>
#include <vector>

#include "photometry/symmetry.h"

namespace luxgrid::photometry {

// (a), on the stored table of any photometric type. `name` starts each warning.
void check_all_zero(const StoredPlanes& planes, const std::string& name,
                    std::vector<std::string>& warnings);

// (b), on the planes of a type C file as stored (before symmetry expansion).
void check_cut_offs(const StoredPlanes& planes, const std::string& name,
                    std::vector<std::string>& warnings);

// (c): `what` names the field ("the luminous area length"), `where` is "name:line".
void check_eulumdat_size_sign(double size_mm, const std::string& what, const std::string& where,
                              std::vector<std::string>& warnings);

// (c) for IES: `year` the file's LM-63 year, sizes in metres as the file gives them (signed).
void check_ies_size_signs(int year, double width_m, double length_m, double height_m,
                          const std::string& name, std::vector<std::string>& warnings);

}  // namespace luxgrid::photometry
