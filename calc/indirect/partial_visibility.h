#pragma once
// Partly hidden patches, resolved cell by cell (docs/indirect.md, "Visibility").
//
// A patch's visible fraction from a point is sampled at five points of the patch
// (patches.h visible_fraction: its centroid and the midpoints towards its corners), which is exact
// for a patch wholly seen or wholly hidden and a fifth of the patch coarse where a shadow edge
// crosses it. Behind the cabinet of examples/lshape and around its reflex corner that coarseness
// was the largest error of `standard`: the reflected light at workplane points in the cabinet's
// shadow moved by up to 2.2 % when their partly hidden patches were resolved by cells, and wall
// points in the arm lit only round the corner by about 1 %.
//
// So a pair whose five samples disagree (0 < fraction < 1: the shadow edge is on the patch) is
// integrated again over the patch's kSubcellsPerSide^2 cells (subcells.h), each with its own form
// factor from the receiver (the point kernel beyond far_ratio x the cell's diameter, Lambert's
// polygon formula closer) and its own visible fraction, the share of the visibility samples that
// are not blocked: every point of `from` to every sample of the cell (its centre, and with
// `cell_midpoints` the midpoints towards its corners too). The cost is paid only by the partial
// pairs, a minority in a room where most pairs see each other wholly.
#include <span>

#include "calc/indirect/patches.h"
#include "geometry/visibility.h"

namespace luxgrid::calc::indirect {

// Sum over the cells of patch `p` (a parallelogram: has_quarters) of weight x form factor from
// (x, n) x visible fraction from the points `from` (the receiver, or a source's sample points,
// lifted off their surface). `cell_weight`: per cell (a * kSubcellsPerSide + b), or null for
// `uniform_weight` on every cell. `lift_m`: how far the cell samples are lifted along p's normal.
double partial_cells_integral(const Vec3& x, const Vec3& n, std::span<const Vec3> from,
                              const Patch& p, const double* cell_weight, double uniform_weight,
                              double far_ratio, const geometry::Visibility& visibility,
                              double lift_m, bool cell_midpoints);

}  // namespace luxgrid::calc::indirect
