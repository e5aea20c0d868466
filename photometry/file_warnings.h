#pragma once
// Warnings on files that read but look wrong, as a manufacturer's checking tool gives them
// (legal but suspicious input: Photometry::warnings, each naming the file). Thresholds are
// named in file_warnings.cpp with the reason for each; they were tuned on the 66 real and
// synthetic files of tests/data/photometry so that well-made files stay quiet.
//
//  (a) the C planes disagree at a pole (gamma 0, or 180 when stored): the pole is one direction,
//      so luxgrid takes their mean (tabular_distribution.h) and says by how much they differ;
//  (b) EULUMDAT's stated LOR or DFF differs from the integral of the table.
// Tables that stop short of a pole, or hold nothing but zeros: table_warnings.h.
#include <string>
#include <vector>

#include "photometry/photometry.h"
#include "photometry/symmetry.h"

namespace luxgrid::photometry {

// (a), on the planes of a type C file as stored (before symmetry expansion and pole
// averaging); the readers call it. `name` starts each warning.
void check_stored_planes(const StoredPlanes& planes, const std::string& name,
                         std::vector<std::string>& warnings);

// (b), on a file as read; load_photometry_text calls it for every file.
void check_stated_ratios(Photometry& p);

}  // namespace luxgrid::photometry
