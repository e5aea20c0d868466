#pragma once
// Grid points in an opening: a window in the wall a grid covers is no surface, so the points that
// lie in it are left out like the points inside obstacles (SurfaceGrid::active = false, counted
// in SurfaceGrid::points_in_openings). Without this, a window wall's minimum and uniformity would
// be those of the hole (docs/project-format.md, results.json's `active`).
#include "calc/scene.h"

namespace luxgrid::calc {

// Leaves out every active point of `grid` (kind grid; named points and observers are kept as
// asked) that lies in the plane of one of the scene's openings (kOpeningPlaneTolerance_m) and
// strictly inside its polygon: a point on the opening's edge lies on the face and stays.
void leave_out_points_in_openings(const Scene& scene, geometry::SurfaceGrid& grid);

}  // namespace luxgrid::calc
