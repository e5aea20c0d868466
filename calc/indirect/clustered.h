#pragma once
// The clustered transfer operator of calc/indirect: the light carried between the patches of one
// room without a dense form-factor matrix, for rooms where nothing blocks light between patches
// (a convex room without obstacles: the plan's visibility is null) and whose patches the dense
// matrix cannot hold (docs/indirect.md, "Large rooms").
//
// Method: a Barnes-Hut clustering of the sources [BarnesHut1986], as in hierarchical radiosity
// with clusters [Hanrahan1991], [Sillion1995], with the receivers kept at single patches. Each
// planar face (a coplanar run of the mesh) gets a binary tree of clusters, split at the median of
// the longest axis of the patch centroids; a node has its area, area-weighted centroid, the
// face's normal and the bounding box of its patches' vertices. Each receiving patch gets an
// interaction list, built once by descending the trees of the other faces: a node is taken whole
// (the point kernel between its centroid and the patch's) when both are smaller than `opening`
// x their distance and each lies wholly in front of the other (the point kernel's error is then
// of second order in that ratio: the first-order terms vanish at the area-weighted centroid for
// a node of uniform exitance); otherwise its children are tried; a single source patch takes the
// dense path's factor (patch_pair_form_factor: exact, quarter rule or point kernel by far_ratio). A
// link is F[node -> patch] per unit flux leaving the node: A_i x kernel / pi.
//
// Storage: neighbouring receivers take mostly the same source nodes, and a node taken whole needs
// nothing but the two centroids and normals for its factor. So the receivers descend in blocks
// of up to 32 patches of one face (ClusterBlock), each source node a block's patches take whole is
// kept once for the block with a 32-bit mask of the patches that take it, and its factors are
// computed in each sweep (whole_node_factor); only the links to single nearby source patches
// (exact or quarter-rule factors, costly) are stored with their factor. On the 200 x 100 x 6 m
// hall at standard: 260 million links in 347 MB, where lists of (node, float) per patch took
// 8 bytes a link (2.1 GB; docs/indirect.md, "Large rooms").
//
// Receivers are not clustered: a receiving cluster spreads what it gathers uniformly over its
// patches, an error of first order in its size (the irradiance from a nearby wall falls across
// it), measured at 25 % of the transferred light on single patches of a 12 x 8 x 3 m room.
//
// One transfer (a sweep): the shot flux of each patch is pulled up the trees (a node's flux is its
// patches' sum) and every patch sums its links, block by block.
//
// Flux conservation: the factor a patch j shoots with in all is the sum over j and its ancestors
// of their links' factors (the light of a node leaves from each of its patches). Each patch's
// shot is scaled by 1 / that sum (source_scale), the equivalent of the dense matrix's per-source
// renormalisation, so a closed room neither creates nor loses light (tests/indirect,
// Clustered.*).
#include <cstdint>
#include <vector>

#include "calc/indirect/limits.h"
#include "calc/indirect/patches.h"
#include "calc/scene.h"
#include "geometry/visibility.h"
#include "util/simd.h"

namespace luxgrid::calc::indirect {

struct ClusterNode {
  Vec3 centroid{0.0};     // area-weighted, m
  Vec3 normal{0.0};       // the face's
  Vec3 lo{0.0}, hi{0.0};  // bounding box of the patches' vertices
  double area_m2 = 0.0;
  double diameter_m = 0.0;  // bounding-box diagonal
  // Children (both or neither); a leaf is one patch, `patch` (room-local index).
  uint32_t child[2] = {kNone, kNone};
  uint32_t patch = kNone;
  static constexpr uint32_t kNone = UINT32_MAX;
};

// The receivers of one descent: at most 32 patches of one face (a subtree of its tree), which
// descend the other faces' trees together and share their lists.
struct ClusterBlock {
  std::vector<uint32_t> leaves;  // the patches' leaf nodes (ClusterNode::patch: the patch)
  // The source nodes its patches take whole, each once for the block: node whole_node[e] is
  // linked to leaves[k] for each bit k of whole_mask[e] (all bits: a node accepted for the
  // block's bounding box). The factor is the point kernel (whole_node_factor), computed from the
  // two nodes in every sweep instead of stored: neighbouring patches take mostly the same nodes,
  // so a node costs 8 bytes per block instead of 8 per patch.
  std::vector<uint32_t> whole_node;
  std::vector<uint32_t> whole_mask;
  // Each patch's links to single source patches, with the dense path's factor
  // (patch_pair_form_factor, stored: mostly exact or quarter-rule factors of nearby patches):
  // those of leaves[k] are [near_begin[k], near_begin[k + 1]), a source leaf and its factor.
  std::vector<uint32_t> near_begin;
  std::vector<uint32_t> near_source;
  std::vector<float> near_factor;
};

struct ClusteredTransfer {
  size_t begin = 0, n = 0;  // patches [begin, begin + n) of the mesh
  // Nodes of all faces, each face's tree in pre-order (a parent before its children).
  std::vector<ClusterNode> nodes;
  std::vector<uint32_t> roots;  // per face
  std::vector<ClusterBlock> blocks;
  std::vector<double> source_scale;  // per patch: kept / its total factor (1 if not renormalised)
  double max_row_correction = 0.0;   // largest |kept - total factor| before renormalisation
  // The acceptance ratio the links were built with: cluster_opening(far_ratio), or wider where
  // that many links would not fit kMaxClusteredLinkBytes (a note says so).
  double opening = 0.0;
  // Links (patch, node) with a factor > 0, shared and own: what a list per patch would hold.
  size_t link_count = 0;
  size_t links() const { return link_count; }
  size_t link_bytes() const;  // memory of the blocks (their nodes and links)
  size_t bytes() const;       // memory of the nodes and blocks
};

// F[a -> b] per unit flux leaving node a, for a node that receiving patch b (its leaf node) takes
// whole: the point kernel between their centroids, b's area x h_src h_dst / (pi d^4), 0 unless
// each centroid lies in front of the other's plane. Computed in
// each sweep (and once for the totals the scale is made from: the same numbers), not stored.
double whole_node_factor(const ClusterNode& a, const ClusterNode& b);

// True when `room` is solved with the clustered transfer at `patch_size_m`: its outline is convex,
// it has no obstacles (nothing blocks light inside it) and its surface area / size^2 exceeds
// kClusteredAbovePatches (limits.h), the most a dense matrix may hold.
bool use_clustered_transfer(const Room& room, double patch_size_m);

// The opening ratio of the clustered links and of the gather's chunk clusters for a far ratio
// (quality): kClusterOpeningScale / far_ratio; reference (far_ratio infinite) uses
// kClusteredReferenceFarRatio. A node is then taken whole only where the dense path would take a
// single patch of that size by the point kernel (patch_pair_form_factor: beyond far_ratio
// diameters), so the clustered room is no coarser than the dense one. A wider ratio is not an
// error bound: the point kernel over a node errs by a few times (opening / 2)^2 per term, and the
// terms do not cancel where a patch sees a whole face at grazing angles (a wall's top row under
// the ceiling). Measured on a 60 x 40 x 3 m room (21 600 patches at 0.5 m, walls and ceiling
// gridded), against the ratio 0.1: 1.23 % at a wall's top corner with the ratio 0.4, 0.23 % with
// standard's 0.2, for 2.1 times the time and 2.8 times the memory (docs/indirect.md).
inline constexpr double kClusterOpeningScale = 1.0;
double cluster_opening(double far_ratio);
// Links per patch of a clustered room, for estimates of its cost before it is meshed
// (calc/pipeline.cpp): measured on the 100 x 50 x 6 m hall, 1 260 at standard's opening 0.2
// (about 50 / opening^2).
inline constexpr double kClusteredLinksPerPatch = 1260.0;
// The far ratio a clustered room uses at `reference` quality, where the dense path is always
// exact: 8 patch (or cluster) diameters, the opening ratio 0.125 (as `high`; the links of a finer
// one would not fit kMaxClusteredLinkBytes on a large hall, where the ratio is widened anyway:
// the 250 000 patches of the largest would need about 2.7 GB at 0.125).
inline constexpr double kClusteredReferenceFarRatio = 8.0;

// The operator of room `room`. `visibility`: what blocks light inside it (null: nothing, a convex
// room without obstacles); see "Visibility per link" above. `renormalise`:
// scale each patch's shot to a total factor of its kept fraction (patches.h: 1 in a closed room,
// less the share leaving through openings). Parallel. Throws
// CalculationError when the links would exceed max_link_bytes (kMaxClusteredLinkBytes, limits.h;
// a larger one only for finer references, IndirectOptions::max_clustered_link_bytes).
ClusteredTransfer clustered_transfer(const PatchMesh& mesh, int room, double far_ratio,
                                     bool renormalise = true,
                                     size_t max_link_bytes = kMaxClusteredLinkBytes,
                                     const geometry::Visibility* visibility = nullptr);

// received[i] = sum over sources j of F[j -> i] x shot[j] x source_scale[j] (room-local
// indices): one sweep of the bounce series, block by block in parallel (the shared links'
// factors computed as it goes). `work` is scratch of nodes.size() doubles.
void apply_clustered(const ClusteredTransfer& T, const std::vector<double>& shot,
                     std::vector<double>& received, std::vector<double>& work);
// Block w's part of a sweep: received[i] for each patch i of the block, from `flux`, the
// scaled shot per node (a node's: the sum of its patches'). apply_clustered calls the version this
// processor runs; the baseline's and AVX2's give the same bits (the tests compare them).
LUXGRID_MULTIVERSION_DECLARE(void, sweep_block,
                             (const ClusteredTransfer& T, size_t w, const double* flux,
                              double* received))

// The form factor F[j -> i] between two patches as the dense matrix computes it (radiosity.h):
// 0 when j lies on or behind i's plane, else the point kernel beyond far_ratio x D_i, the
// quarter rule between half that and far_ratio x D_i, Lambert's exact formula closer; no
// visibility.
double patch_pair_form_factor(const Patch& source, const Patch& receiver, double far_ratio);
// The same from a source point and normal (the dense matrix passes its chunk's normal), with
// near_d2 = (far_ratio x the receiver's diameter)^2.
double patch_pair_form_factor(const Vec3& source_centroid, const Vec3& source_normal,
                              const Patch& receiver, double near_d2);

}  // namespace luxgrid::calc::indirect
