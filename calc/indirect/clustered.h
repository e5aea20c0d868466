#pragma once
// The clustered transfer operator of calc/indirect: the light carried between the patches of one
// room without a dense form-factor matrix, for rooms where nothing blocks light between patches
// (a convex room without obstacles: the plan's visibility is null) and whose patches the dense
// matrix cannot hold (docs/indirect.md, "Large rooms").
//
// Method: hierarchical radiosity with clusters [Hanrahan1991], [Sillion1995]. Each planar face
// (a coplanar run of the mesh) gets a binary tree of clusters, split at the median of the longest
// axis of the patch centroids; a node has its area, area-weighted centroid, the face's normal and
// the bounding box of its patches' vertices. Links between a source node A and a receiver node B
// are refined once, from the face pairs down: a pair is linked with the point kernel between the
// nodes' centroids when both diameters are below `opening` x the centroid distance and each node
// lies wholly in front of the other's plane (the opening-angle test of [BarnesHut1986]: the
// point kernel's relative error goes as (diameter / distance)^2, as the far kernel of the dense
// path does at its far switch); otherwise the larger node is split; two single patches take the
// dense path's factor (patch_pair_form_factor: exact, quarter rule or point kernel by far_ratio).
// A link stores F[A -> B] per unit flux leaving A: A_B x kernel / pi.
//
// One transfer (a sweep): the shot flux of each patch is pulled up the trees (a node's flux is its
// patches' sum), every receiver node gathers over its links, and what a node receives is pushed
// down to its patches in proportion to their area (uniform irradiance over the node).
//
// Flux conservation: the factor a patch j shoots with in all is the sum over j and its ancestors
// of their links' factors (the light of a node leaves from each of its patches). Each patch's
// shot is scaled by 1 / that sum (source_scale), the equivalent of the dense matrix's per-source
// renormalisation, so a closed room neither creates nor loses light (tests/indirect,
// Clustered.*). The push-down splits a node's incident flux by area fractions that sum to 1, so
// the flux that leaves equals the flux that lands, to rounding.
#include <cstdint>
#include <vector>

#include "calc/indirect/patches.h"
#include "calc/scene.h"

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

struct ClusteredTransfer {
  size_t begin = 0, n = 0;  // patches [begin, begin + n) of the mesh
  // Nodes of all faces, each face's tree in pre-order (a parent before its children).
  std::vector<ClusterNode> nodes;
  std::vector<uint32_t> roots;  // per face
  // Links by receiver node (compressed rows): links of node b are [link_begin[b],
  // link_begin[b + 1]) with source node link_source[k] and factor link_factor[k] (F per unit
  // flux leaving the source node).
  std::vector<uint64_t> link_begin;
  std::vector<uint32_t> link_source;
  std::vector<float> link_factor;
  std::vector<double> source_scale;  // per patch: 1 / its total factor (1 if not renormalised)
  double max_row_correction = 0.0;   // largest |1 - total factor| before renormalisation
  double opening = 0.0;              // the acceptance ratio the links were built with
  size_t links() const { return link_source.size(); }
  size_t bytes() const;  // memory of the nodes and links
};

// True when `room` is solved with the clustered transfer at `patch_size_m`: its outline is convex,
// it has no obstacles (nothing blocks light inside it) and its surface area / size^2 exceeds
// kClusteredAbovePatches (limits.h), the most a dense matrix may hold.
bool use_clustered_transfer(const Room& room, double patch_size_m);

// The opening ratio of the clustered links for a far ratio (quality): 1 / far_ratio, so that a
// cluster is linked only as far away (in its diameters) as the dense path takes a single patch's
// point kernel; reference (far_ratio infinite) uses kClusteredReferenceFarRatio.
double cluster_opening(double far_ratio);
// The far ratio a clustered room uses at `reference` quality, where the dense path is always
// exact: 16 patch (or cluster) diameters, a point-kernel error of (1/16)^2 / (2 pi) = 0.06 %
// per term, twice as strict as `high`'s 8.
inline constexpr double kClusteredReferenceFarRatio = 16.0;

// The operator of room `room` (its visibility must be null: nothing blocks). `renormalise`:
// scale each patch's shot to a total factor of 1 (closed rooms). Parallel. Throws
// CalculationError when the links would exceed kMaxClusteredLinkBytes (limits.h).
ClusteredTransfer clustered_transfer(const PatchMesh& mesh, int room, double far_ratio,
                                     bool renormalise = true);

// received[i] = sum over sources j of F[j -> i] x shot[j] x source_scale[j] (room-local
// indices): one sweep of the bounce series. `work` is scratch of nodes.size() doubles x 2.
void apply_clustered(const ClusteredTransfer& T, const std::vector<double>& shot,
                     std::vector<double>& received, std::vector<double>& work);

// The form factor F[j -> i] between two patches as the dense matrix computes it (radiosity.h):
// 0 when j lies on or behind i's plane, else the point kernel beyond far_ratio x D_i, the
// quarter rule between half that and far_ratio x D_i, Lambert's exact formula closer; no
// visibility.
double patch_pair_form_factor(const Patch& source, const Patch& receiver, double far_ratio);

}  // namespace luxgrid::calc::indirect
