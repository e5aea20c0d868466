#pragma once
// The limits of the indirect calculation (docs/indirect.md, "Limits"): each bounds the memory or
// the time of one stage, whatever the project asks for.
#include <cstddef>

namespace luxgrid::calc::indirect {

// The default budget of patches per room (IndirectOptions::max_patches_per_room): the dense
// form-factor matrix of a room holds n^2 floats, 64 MB at 4000 patches, which the solve streams
// once per bounce (about 5 ms a sweep on two cores); the size grows to fit it.
inline constexpr size_t kDefaultPatchesPerRoom = 4000;
// The largest budget a caller may set (a larger one is lowered to it, with a note): 10 000
// patches, a matrix of 400 MB (0.25 m patches on a 25 x 25 x 3 m room), ~30 ms a sweep.
inline constexpr size_t kMaxPatchesPerRoom = 10000;
// Rooms are solved one after the other and each matrix is freed before the next is built, so
// this is the most the matrices ever take, however many rooms there are.
inline constexpr size_t kMaxFormFactorMatrixBytes =
    sizeof(float) * kMaxPatchesPerRoom * kMaxPatchesPerRoom;
// For messages: decimal megabytes, as the figures above are given.
inline constexpr size_t kBytesPerMegabyte = 1000000;
// Patches in all rooms together at most. A patch with its polygon, first-bounce and gather
// entries takes about 0.5 kB, so 100 000 patches (25 rooms at the full per-room budget) take
// about 50 MB beside the one matrix; and the final gather visits every patch of a point's room.
inline constexpr size_t kMaxTotalPatches = 100000;
// Rooms where nothing blocks light between patches (a convex outline without obstacles) whose
// mesh at the requested patch size has more patches than this (the most a dense matrix may ever
// hold, kMaxPatchesPerRoom) are solved with the clustered transfer (clustered.h) at that size
// instead of a coarser dense mesh. Below it the dense path holds the room at most
// sqrt(10 000 / 4 000) = 1.6 times coarser than asked, and its results stay exactly as they were.
inline constexpr size_t kClusteredAbovePatches = kMaxPatchesPerRoom;
// Rooms where something blocks light (a reflex corner, obstacles) whose mesh at the requested
// patch size has more patches than this are solved with the clustered transfer with visibility
// per link (clustered.h): in the dense matrix each of the n^2 pairs may trace rays, about 8 times
// the work of an unobstructed pair (calc/pipeline.cpp), 1e7 at 1 100 patches.
inline constexpr size_t kClusteredVisibleAbovePatches = 1100;
// Patches per clustered room at most: 174 400 patches mesh a 200 x 100 x 6 m hall at 0.5 m; a
// patch with its polygon, tree node and gather entry takes about 0.7 kB, and its links about
// 170 / opening^2 bytes at most (clustered.h: shared per block of patches, only the near ones
// stored with their factor; 2 kB at standard on that hall, 4 kB at a patch size of 1 m), so
// 250 000 patches take about 0.7 GB at standard; at high or reference the links' own limit below
// widens the opening ratio (clustered.h). Above it the patch size grows to fit, as for the dense
// budget.
inline constexpr size_t kMaxClusteredPatchesPerRoom = 250000;
// The links of one clustered room at most (ClusteredTransfer::link_bytes: 8 bytes per whole node
// of a block, 8 per near link): rooms are solved one after the other and each room's links are
// freed before the next, as the dense matrices are.
inline constexpr size_t kMaxClusteredLinkBytes = size_t(1500) * 1000000;
// Patches in all clustered rooms together at most (the dense rooms count against
// kMaxTotalPatches): 300 000 patches, about 150 MB with their polygons and gather entries.
inline constexpr size_t kMaxClusteredTotalPatches = 300000;
// Reflections at most, explicit (`bounces: N`, also checked by the project loader) or auto: a
// room of reflectance 1 absorbs nothing and the series never converges, so auto mode stops here
// and reports the remainder as its residual. 1000 sweeps of the largest matrix take ~5 s.
inline constexpr int kMaxBounces = 1000;

}  // namespace luxgrid::calc::indirect
