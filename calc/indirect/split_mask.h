#pragma once
// Which patches of a solved room to cut into quarters before solving it again (docs/indirect.md,
// "Patches split where the light changes"). A patch carries one exitance, its mean; where the
// light changes steeply across it (a shadow edge cast by an obstacle or a reflex corner, a wall
// washed from close by), the receivers that see it take that mean instead of the light's shape,
// an error of the first order in the patch's size, and refining the whole room to remove it costs
// every pair of patches [CohenWallace1993, Ch. 8]. The jump between a patch's exitance and its
// neighbours' on the same face says where the light changes: measured on examples/lshape and
// tests/rooms/ushape against the same rooms solved at 0.15 and 0.19 m, cutting the patches whose
// exitance differs from a neighbour's by more than 30 % of the larger takes `standard`'s worst
// points from 1.89 % to 1.11 % and from 3.08 % to 0.58 %, with about half the patches of a uniform
// mesh at half the size (docs/indirect.md, "Patches split where the light changes").
#include <cstddef>
#include <vector>

#include "calc/indirect/patches.h"

namespace luxgrid::calc::indirect {

// The jump every quality but `draft` cuts at: 30 % of the larger exitance (measured above).
inline constexpr double kSplitJump = 0.3;

// Per patch of `mesh` (1: cut it) among the patches [begin, end) of one room: a parallelogram
// (Patch::has_quarters) whose exitance per area differs from that of a neighbour by more than
// `jump` x the larger of the two. Neighbours: patches of the same face (kind, index and normal)
// whose centroids lie within 0.55 x the sum of their diameters (edge and corner neighbours of a
// grid). At most `max_added` patches are added (3 per cut patch): beyond, the largest jumps are
// cut first (ties by index, so the choice is the same on every run).
std::vector<char> patches_to_split(const PatchMesh& mesh, size_t begin, size_t end,
                                   const std::vector<double>& exitant_flux_lm, double jump,
                                   size_t max_added);

// The exitant flux of the patches [begin, end) of one room before it is solved (the entries of
// other rooms 0), for patches_to_split: each patch's reflectance times its first-bounce flux
// plus its area times the mean reflected irradiance of a closed room of the area-weighted mean
// reflectance rho_m, sum_j rho_j Phi_j / (A (1 - rho_m)) (the ambient term of progressive
// refinement, [CohenWallace1993]). The reflected light spread evenly damps the first bounce's jumps
// about as a solve does where the reflected light changes slowly, which is where rooms with the
// clustered transfer choose their split without solving the unsplit mesh first (indirect.cpp).
std::vector<double> ambient_exitance(const PatchMesh& mesh, size_t begin, size_t end,
                                     const std::vector<double>& incident_flux_lm);

}  // namespace luxgrid::calc::indirect
