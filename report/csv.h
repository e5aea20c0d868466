#pragma once
// One CSV per surface: a row per point with position, normal, whether it is calculated, the three
// maintained illuminances and the quantity they measure (planar, ..., semi-cylindrical).
#include <ostream>
#include <string>

#include "calc/results.h"

namespace luxgrid::report {

// The header row: the E columns say in their names that they are maintained values.
inline constexpr const char* kSurfaceCsvHeader =
    "i,j,x,y,z,nx,ny,nz,active,E_maintained_lx,E_direct_maintained_lx,E_indirect_maintained_lx,"
    "quantity";
// The daylight scene's columns after those (percent of E_h; docs/daylight.md).
inline constexpr const char* kDaylightCsvColumns = ",DF_percent,SC_percent,ERC_percent,IRC_percent";
// With direct sun after those: the sun's direct and reflected parts of E, lx.
inline constexpr const char* kSunCsvColumns = ",E_sun_direct_lx,E_sun_reflected_lx";

std::string surface_csv(const calc::SurfaceResult& r);
// The same text written to `out`, its rows formatted in parallel a chunk at a time: what the
// output folder's <surface>.csv is written with.
void write_surface_csv(std::ostream& out, const calc::SurfaceResult& r);

}  // namespace luxgrid::report
