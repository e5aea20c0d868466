#pragma once
// A surface's results as one .npy array (report/npy.h), for grids too large to read back from
// results.json comfortably: shape (points, 6), one row per point in the order of the CSV
// (u fastest), columns x, y, z (m), E, E_direct, E_indirect (lx; E after the maintenance factor,
// its parts initial, as in the CSV).
#include <string>

#include "calc/results.h"

namespace luxgrid::report {

inline constexpr int kSurfaceNpyColumns = 6;

std::string surface_npy(const calc::SurfaceResult& r);

}  // namespace luxgrid::report
