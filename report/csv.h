#pragma once
// One CSV per surface: a row per point with position, normal, the three illuminances and the
// quantity they measure (planar, ..., semi-cylindrical).
#include <string>

#include "calc/results.h"

namespace luxgrid::report {

std::string surface_csv(const calc::SurfaceResult& r);

}  // namespace luxgrid::report
