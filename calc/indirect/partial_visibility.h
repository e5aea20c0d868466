#pragma once
// Partly hidden patches, resolved cell by cell (docs/indirect.md, "Visibility").
//
// A patch's visible fraction from a point sampled at five points of the patch
// (patches.h visible_fraction: its centroid and the midpoints towards its corners) is exact for a
// patch wholly seen or wholly hidden, a fifth of the patch coarse where a shadow edge crosses it,
// and blind to an edge that passes between the samples: behind the cabinet of examples/lshape the
// reflected light at workplane points in its shadow moved by up to 2.9 % when the partly hidden
// patches were resolved as below (wall points by up to 1.1 %), and a workplane point 2 mm from the
// cabinet's face, whose view of the wall beyond it is cut by the cabinet's end, took a wall
// patch crossed 0.03 m from its border as wholly seen: 1.4 % too much light at 0.25 m patches,
// 0.3 % at 0.2 m, where the edge happened to pass a sample.
//
// So a patch the shaft test cannot decide is first given its own shaft verdict (geometry/shaft.h:
// `visible` or `hidden` is a proof for every segment to it), and one that stays partial is
// integrated over its kSubcellsPerSide^2 cells (subcells.h), each with its own form factor from
// the receiver (the point kernel beyond far_ratio x the cell's diameter, Lambert's polygon formula
// closer) and its own visibility:
// - each cell's centre, tested against the faces the patch's verdict left undecided where it
//   narrowed them to a few (geometry/visibility.h ShaftFaces), traced otherwise; where a
//   neighbouring cell's centre gets the other verdict (the edge runs through or beside it), the
//   share of five samples (its centre and the midpoints towards its corners) that are seen: the
//   edge placed to within half a cell, for 16 tests plus 4 per edge cell;
// - where every centre agrees although the patch's verdict is partial (the edge passes between
//   them) and the faces are narrowed, each cell's own shaft verdict among them, and a cell still
//   partial its five samples: no edge is missed.

#include "calc/indirect/patches.h"
#include "geometry/visibility.h"

namespace luxgrid::calc::indirect {

// Sum over the cells of patch `p` (a parallelogram: has_quarters) of weight x form factor from
// (x, n) x visible share seen from `from` (the receiver lifted off its surface). `cell_weight`:
// per cell (a * kSubcellsPerSide + b), or null for `uniform_weight` on every cell. `lift_m`: how
// far the cell samples are lifted along p's normal (so p's own face does not hide them). `faces`:
// the faces p's own shaft verdict left undecided (a ShaftFaces{}, not narrowed, when unknown).
double partial_cells_integral(const Vec3& x, const Vec3& n, const Vec3& from, const Patch& p,
                              const double* cell_weight, double uniform_weight, double far_ratio,
                              const geometry::Visibility& visibility, double lift_m,
                              const geometry::ShaftFaces& faces = geometry::ShaftFaces{});

// The light (lx, or a form factor times a weight) from patch `p` at (x, n) when a coarser shaft
// verdict left it undecided, with the faces it left (`among`; ShaftFaces{}: every face): `whole`
// (what it gives wholly seen) when its own shaft verdict says `visible`, 0 when `hidden`,
// partial_cells_integral otherwise. `p` must be a parallelogram.
double undecided_patch_integral(const Vec3& x, const Vec3& n, const Vec3& from, const Patch& p,
                                const double* cell_weight, double uniform_weight, double whole,
                                double far_ratio, const geometry::Visibility& visibility,
                                double lift_m, const geometry::ShaftFaces& among);

}  // namespace luxgrid::calc::indirect
