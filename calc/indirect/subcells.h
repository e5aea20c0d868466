#pragma once
// Patches refined into cells for the receivers close to them (the final gather, gather.h).
//
// The radiosity solve gives one exitance per patch, its mean. A receiver farther than a few patch
// diameters sees only that mean; a receiver closer sees mostly the part of the patch nearest to
// it, whose exitance may differ from the mean by much. In a room this is largest in the corners:
// a ceiling point 0.125 m from a wall, beside 0.5 m wall patches whose exitance falls towards the
// ceiling, gathers 3.6 % too much with patch-constant exitance, and a wall point near the ceiling
// 4 % (examples/office against `reference`, which meshes at 0.2 m).
//
// Each patch that a receiver sees from closer than kSubcellReach diameters is cut into
// kSubcellsPerSide^2 cells, and each cell gets the exitance the patch's own equation gives it:
//   M_cell = M_patch + rho (E_direct,cell - mean E_direct,cells)
//                    + rho (E_indirect,cell - mean E_indirect,cells),
// E_direct,cell from the first bounce integrated over the cell (first_bounce.h, as for patches),
// E_indirect,cell gathered at the cell's centre from the solved patches within kCellNearGather
// patch sizes, plus the light of all farther patches gathered at the patch's four corners and
// interpolated bilinearly (it varies smoothly over one patch, but it does vary: leaving it out,
// as a part common to all cells, leaves 3 % of the 4 % at the office's corners). Refined patches
// of one face that meet at a corner share its gather (far_corners), so a face refined all over
// costs about one such gather per patch instead of four. Both
// differences have mean 0 over the patch, so every patch keeps its flux (the solve's energy balance
// is untouched); only how the flux is spread over the patch changes. The cells' own E_indirect
// comes from patch-constant exitance, so the refinement is one level deep: its error is that of the
// patch mesh times rho, at the cells only. A negative M_cell (a steep gradient at a shadow edge) is
// clamped at 0. This is the local "final gather" refinement of radiosity practice
// ([CohenWallace1993, Ch. 8 and 9]: a second pass gathering at higher resolution where the
// receiver needs it).
#include <array>
#include <vector>

#include "calc/indirect/patches.h"
#include "calc/scene.h"
#include "geometry/visibility.h"

namespace luxgrid::calc::indirect {

// Cells per side of a refined patch: 0.5 m patches give 0.125 m cells, the spacing of a fine
// wall grid.
inline constexpr int kSubcellsPerSide = 4;
// A receiver closer to a patch's centroid than this many patch diameters gathers the patch cell
// by cell. Measured on examples/office at 0.5 m patches against `reference`: largest difference
// 4.1 % with no cells, 0.75 % with a reach of 1, 0.5 % with 2 (at more than twice the cost).
inline constexpr double kSubcellReach = 1.0;

// Patches within this many patch sizes of a cell are gathered at the cell itself.
inline constexpr double kCellNearGather = 3.0;

// The corners of cell (a, b) of a parallelogram patch, counter-clockwise like the patch:
// a along the edge from corner 0 to 1, b along the edge from 0 to 3.
using SubcellCorners = std::array<Vec3, 4>;
SubcellCorners subcell_corners(const Patch& p, int a, int b);

// The form factor from the point (x, n) to one cell of patch p (its corners and centre): the point
// kernel on the cell beyond sqrt(near_d2) (far_ratio x the cell's diameter), Lambert's polygon
// formula closer. The final gather's cells (gather.cpp) and partly hidden patches
// (partial_visibility.h) both take it.
double subcell_form_factor(const Vec3& x, const Vec3& n, const Patch& p, const SubcellCorners& cell,
                           const Vec3& centre, double cell_area_m2, double near_d2);

struct SubcellExitance {
  // Per patch of the mesh: the index in exitance_lm_m2 of its first cell, or -1 (not refined).
  std::vector<long> first;
  // kSubcellsPerSide^2 per refined patch, cell (a, b) at a * kSubcellsPerSide + b.
  std::vector<double> exitance_lm_m2;
  size_t refined_patches = 0;
};

// The cells of the patches marked in `refine` (parallelograms only: patches.h has_quarters) as a
// mesh of their own (room by room, for first_bounce), and each cell's patch. indirect.cpp then
// integrates the first bounce over the cells, gathers E_indirect at their centres and calls
// cell_exitance.
struct CellMesh {
  PatchMesh mesh;
  std::vector<size_t> patch;  // per cell
};
CellMesh cell_mesh(const PatchMesh& mesh, const std::vector<char>& refine);

// Where the far part of the refined patches' cells is gathered: each distinct corner of the
// patches of `cells` once. Corners are the same where their positions round to the same
// micrometre on patches of one room whose normals round to the same millionths (one face, or
// coplanar ones), so the patches of a face that meet at a corner share it, and two faces meeting
// at an edge do not. Two computations of one corner that straddle a rounding boundary (1e-12 m
// apart) are gathered twice, each at its own position: one gather more, never a wrong one.
struct FarCorners {
  struct Corner {
    int room = 0;
    Vec3 x{0.0};
    Vec3 normal{0.0};
  };
  std::vector<Corner> corners;
  // Per refined patch (cells come kSubcellsPerSide^2 per patch, cell_mesh): its polygon's four
  // corners as indices into `corners`.
  std::vector<std::array<size_t, 4>> of_patch;
};
FarCorners far_corners(const PatchMesh& mesh, const CellMesh& cells);

// The bilinear weight of the patch's corner k (polygon order: 0, 1 along a, 2, 3 along b) at the
// centre of cell (a, b): ((a + 1/2) / n, (b + 1/2) / n) in the patch's own coordinates.
double far_corner_weight(int a, int b, int k);

// M_cell from the cells' direct incident flux and gathered E_indirect, as above.
SubcellExitance cell_exitance(const PatchMesh& mesh, const CellMesh& cells,
                              const std::vector<double>& exitant_flux_lm,
                              const std::vector<double>& cell_incident_flux_lm,
                              const std::vector<double>& cell_indirect_lx);

}  // namespace luxgrid::calc::indirect
