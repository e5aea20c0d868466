#pragma once
// Partly hidden patches, resolved cell by cell (docs/indirect.md, "Visibility").
//
// A patch's visible fraction from a point is sampled at five points of the patch
// (patches.h visible_fraction: its centroid and the midpoints towards its corners), which is exact
// for a patch wholly seen or wholly hidden and a fifth of the patch coarse where a shadow edge
// crosses it. Behind the cabinet of examples/lshape the reflected light at workplane points in its
// shadow moved by up to 2.9 % when the partly hidden patches were resolved as below (wall points
// by up to 1.1 %), so the five samples alone are not within `standard`'s promise there.
//
// So a patch whose five samples disagree (0 < fraction < 1: a shadow edge crosses it) is
// integrated again over its kSubcellsPerSide^2 cells (subcells.h), each with its own form factor
// from the receiver (the point kernel beyond far_ratio x the cell's diameter, Lambert's polygon
// formula closer) and its own visibility: its centre's, and where a neighbouring cell's centre
// gets the other verdict (the edge runs through or beside it) the share of five samples (the
// centre and the midpoints towards its corners) that are seen. The edge is then placed to within
// half a cell, for 16 rays plus 4 per edge cell, paid only by the partly hidden patches.

#include "calc/indirect/patches.h"
#include "geometry/visibility.h"

namespace luxgrid::calc::indirect {

// Sum over the cells of patch `p` (a parallelogram: has_quarters) of weight x form factor from
// (x, n) x visible share seen from `from` (the receiver lifted off its surface). `cell_weight`:
// per cell (a * kSubcellsPerSide + b), or null for `uniform_weight` on every cell. `lift_m`: how
// far the cell samples are lifted along p's normal (so p's own face does not hide them).
double partial_cells_integral(const Vec3& x, const Vec3& n, const Vec3& from, const Patch& p,
                              const double* cell_weight, double uniform_weight, double far_ratio,
                              const geometry::Visibility& visibility, double lift_m);

}  // namespace luxgrid::calc::indirect
