#include "calc/indirect/clustered.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "calc/indirect/form_factor.h"
#include "calc/indirect/limits.h"
#include "geometry/box3.h"
#include "geometry/shaft.h"
#include "util/error.h"
#include "util/simd.h"

namespace luxgrid::calc::indirect {

using geometry::box_max_height;
using geometry::box_min_height;

namespace {
// A node lies "wholly in front" of a plane when no vertex of its box is farther behind it than
// this (adjacent faces share an edge, at height 0 up to rounding).
constexpr double kFrontTolerance_m = 1e-9;
// Receiving patches that descend the source trees together (one block: a subtree of nearby
// patches, so that most nodes are decided for all of them at once), and blocks refined at a time
// before their links are appended (16 384 patches).
constexpr size_t kBlockPatches = 32;
// bit[k] = 1 << k: the mask bit of a block's k-th patch (a table, so that the loops over the
// patches vectorise).
constexpr auto kBits = [] {
  std::array<uint32_t, kBlockPatches> b{};
  for (size_t k = 0; k < kBlockPatches; ++k) b[k] = uint32_t(1) << k;
  return b;
}();
constexpr size_t kWaveBlocks = 512;
// Blocks whose factors are summed into one partial total per node (2 048 patches), and ranges
// summed at a time (each a partial of the nodes' count of doubles).
constexpr size_t kSumBlocks = 64;
constexpr size_t kSumWave = 8;
// Stored bytes per patch times opening^2 (ClusterBlock: 8 bytes per whole node of a block, 8 per
// near link), measured at standard's opening 0.2: the 100 x 50 x 6 m hall 87 at 0.5 m patches,
// 157 at 1 m; the 200 x 100 x 6 m hall 80 and 161 (at 1 m more of the patches lie near an edge,
// where the links are near ones).
constexpr double kStoredBytesPerPatchOpening2 = 170.0;

// Builds the tree of patches idx[lo, hi) (room-local), pre-order, returns its root.
uint32_t build_tree(const PatchMesh& mesh, size_t begin, std::vector<uint32_t>& idx, size_t lo,
                    size_t hi, std::vector<ClusterNode>& nodes) {
  const uint32_t id = static_cast<uint32_t>(nodes.size());
  nodes.emplace_back();
  ClusterNode node;
  node.lo = Vec3(std::numeric_limits<double>::infinity());
  node.hi = Vec3(-std::numeric_limits<double>::infinity());
  Vec3 clo = node.lo, chi = node.hi, moment(0.0);
  for (size_t k = lo; k < hi; ++k) {
    const Patch& p = mesh.patches[begin + idx[k]];
    node.area_m2 += p.area_m2;
    moment += p.area_m2 * p.centroid;
    clo = glm::min(clo, p.centroid), chi = glm::max(chi, p.centroid);
    for (const auto& v : p.polygon) node.lo = glm::min(node.lo, v), node.hi = glm::max(node.hi, v);
  }
  node.normal = mesh.patches[begin + idx[lo]].normal;
  node.diameter_m = glm::length(node.hi - node.lo);
  if (hi - lo == 1) {
    node.centroid = mesh.patches[begin + idx[lo]].centroid;
    node.patch = idx[lo];
    nodes[id] = node;
    return id;
  }
  node.centroid = moment / node.area_m2;
  const Vec3 ext = chi - clo;
  const int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : ext.y >= ext.z ? 1 : 2;
  const size_t mid = lo + (hi - lo) / 2;
  std::nth_element(idx.begin() + static_cast<long>(lo), idx.begin() + static_cast<long>(mid),
                   idx.begin() + static_cast<long>(hi), [&](uint32_t a, uint32_t b) {
                     const double ca = mesh.patches[begin + a].centroid[axis];
                     const double cb = mesh.patches[begin + b].centroid[axis];
                     return ca < cb || (ca == cb && a < b);
                   });
  node.child[0] = build_tree(mesh, begin, idx, lo, mid, nodes);
  node.child[1] = build_tree(mesh, begin, idx, mid, hi, nodes);
  nodes[id] = node;
  return id;
}

bool is_leaf(const ClusterNode& c) { return c.child[0] == ClusterNode::kNone; }

// whole_node_factor from the parts: source a's centroid and normal, receiver b's normal,
// centroid (bx, by, bz) and area. In components and branch-free (the tests applied to the
// computed value), so that the loops over a block's patches vectorise; d2 > 0 between the
// centroids of two faces.
LUXGRID_LANE double node_factor(const Vec3& a_centroid, const Vec3& a_normal, const Vec3& b_normal,
                                double bx, double by, double bz, double b_area_m2) {
  const double dx = bx - a_centroid.x, dy = by - a_centroid.y, dz = bz - a_centroid.z;
  const double h_src = a_normal.x * dx + a_normal.y * dy + a_normal.z * dz;
  const double h_dst = -(b_normal.x * dx + b_normal.y * dy + b_normal.z * dz);
  const double f =
      b_area_m2 * point_kernel_pi_per_m2(h_src, h_dst, dx * dx + dy * dy + dz * dz) / kPi;
  return h_src > 0.0 && h_dst > 0.0 ? f : 0.0;
}

// A block's patches' geometry as arrays, for the loops over them.
struct BlockLeaves {
  size_t count = 0;
  Vec3 normal{0.0};  // one face's
  double x[kBlockPatches], y[kBlockPatches], z[kBlockPatches], area_m2[kBlockPatches];

  LUXGRID_LANE BlockLeaves(const ClusterBlock& blk, const std::vector<ClusterNode>& nodes)
      : count(blk.leaves.size()) {
    for (size_t k = 0; k < count; ++k) {
      const ClusterNode& b = nodes[blk.leaves[k]];
      normal = b.normal;
      x[k] = b.centroid.x, y[k] = b.centroid.y, z[k] = b.centroid.z, area_m2[k] = b.area_m2;
    }
  }
  // whole_node_factor(a, leaf k) for each bit k of `mask` (0 elsewhere), into f.
  LUXGRID_LANE void factors(const ClusterNode& a, uint32_t mask, double* f) const {
    for (size_t k = 0; k < count; ++k) {
      const double v = node_factor(a.centroid, a.normal, normal, x[k], y[k], z[k], area_m2[k]);
      f[k] = (kBits[k] & mask) != 0 ? v : 0.0;
    }
  }
};

// Some part of each of the two clusters lies in front of the other's plane. If not, one is wholly
// on or behind the other's plane and every factor between their patches is 0.
bool face_each_other(const ClusterNode& a, const ClusterNode& b) {
  return box_max_height(a.normal, a.centroid, b.lo, b.hi) > kEdgeOnDistance_m &&
         box_max_height(b.normal, b.centroid, a.lo, a.hi) > kEdgeOnDistance_m;
}

// Per node, the boxes of the points its patches' visibility segments end at: where each patch
// shoots from (its centroid, as the dense matrix, radiosity.cpp) and where it is looked at
// (visible_fraction's sample points: the centroid and the midpoints towards its corners). Both
// lie inside the node's vertex box by a quarter of a patch and more, so the shaft of a node
// along a wall does not graze that wall, which would leave it `partial`.
struct SegmentEnds {
  std::vector<geometry::Box3> shoot, sample;
};
SegmentEnds segment_ends(const PatchMesh& mesh, size_t begin,
                         const std::vector<ClusterNode>& nodes) {
  SegmentEnds e;
  e.shoot.resize(nodes.size());
  e.sample.resize(nodes.size());
  for (size_t a = nodes.size(); a-- > 0;) {  // pre-order: children after their parent
    const ClusterNode& c = nodes[a];
    if (is_leaf(c)) {
      const Patch& p = mesh.patches[begin + c.patch];
      e.shoot[a] = e.sample[a] = {p.centroid, p.centroid};
      for (const Vec3& v : p.polygon) {
        const Vec3 m = 0.5 * (v + p.centroid);
        e.sample[a].lo = glm::min(e.sample[a].lo, m), e.sample[a].hi = glm::max(e.sample[a].hi, m);
      }
      continue;
    }
    for (std::vector<geometry::Box3>* boxes : {&e.shoot, &e.sample}) {
      const geometry::Box3 &l = (*boxes)[c.child[0]], &r = (*boxes)[c.child[1]];
      (*boxes)[a] = {glm::min(l.lo, r.lo), glm::max(l.hi, r.hi)};
    }
  }
  return e;
}

// The shaft verdict (geometry/shaft.h) for the segments between source node a's shooting points
// and receiving node b's sample points, each box moved off its face by the lift, decided among
// the faces `among` (those a shaft holding this one left undecided: the verdict of a's parent
// against b; ShaftFaces{}: every face); where `partial`, the faces it leaves into `undecided`.
geometry::Shaft node_verdict(const geometry::Visibility& visibility, const SegmentEnds& ends,
                             const std::vector<ClusterNode>& nodes, uint32_t a, uint32_t b,
                             const geometry::ShaftFaces& among, geometry::ShaftFaces& undecided) {
  std::array<Vec3, 8> source, receiver;
  const size_t ns = geometry::box_element(ends.shoot[a].lo, ends.shoot[a].hi,
                                          nodes[a].normal * kShootLift_m, source);
  const size_t nr = geometry::box_element(ends.sample[b].lo, ends.sample[b].hi,
                                          nodes[b].normal * kShootLift_m, receiver);
  return visibility.classify_within(std::span<const Vec3>(source.data(), ns),
                                    std::span<const Vec3>(receiver.data(), nr), among, undecided);
}

}  // namespace

size_t ClusteredTransfer::link_bytes() const {
  size_t b = blocks.size() * sizeof(ClusterBlock);
  for (const ClusterBlock& blk : blocks)
    b += (blk.leaves.capacity() + blk.whole_node.capacity() + blk.whole_mask.capacity() +
          blk.near_begin.capacity() + blk.near_source.capacity()) *
             sizeof(uint32_t) +
         blk.near_factor.capacity() * sizeof(float);
  return b;
}

size_t ClusteredTransfer::bytes() const {
  return nodes.size() * sizeof(ClusterNode) + link_bytes() + n * sizeof(double);
}

double whole_node_factor(const ClusterNode& a, const ClusterNode& b) {
  return node_factor(a.centroid, a.normal, b.normal, b.centroid.x, b.centroid.y, b.centroid.z,
                     b.area_m2);
}

bool use_clustered_transfer(const Room& room, double patch_size_m) {
  const double patches = room_surface_area(room) / (patch_size_m * patch_size_m);
  const bool unobstructed = outline_is_convex(room) && room.obstacles.empty();
  return patches >
         static_cast<double>(unobstructed ? kClusteredAbovePatches : kClusteredVisibleAbovePatches);
}

double cluster_opening(double far_ratio) {
  return kClusterOpeningScale /
         (std::isfinite(far_ratio) ? far_ratio : kClusteredReferenceFarRatio);
}

double patch_pair_form_factor(const Vec3& source_centroid, const Vec3& source_normal,
                              const Patch& receiver, double near_d2) {
  const Vec3 d = receiver.centroid - source_centroid;  // source -> receiver
  const double h_dst = -glm::dot(receiver.normal, d);  // source's height over the receiver's plane
  if (!(h_dst > kEdgeOnDistance_m)) return 0.0;
  const double h_src = glm::dot(source_normal, d);
  if (!(h_src > -receiver.diameter_m)) return 0.0;
  const double d2 = glm::dot(d, d);
  // Far: point_kernel_form_factor(source, receiver) without its tests (done above).
  if (d2 > near_d2)
    return h_src > 0.0 ? receiver.area_m2 * point_kernel_pi_per_m2(h_src, h_dst, d2) / kPi : 0.0;
  // Between far_ratio x D / 2 and far_ratio x D: the kernel on the quarters; closer: exact.
  double f = receiver.has_quarters
                 ? quarter_kernel_form_factor(source_centroid, source_normal, receiver.polygon,
                                              receiver.centroid, receiver.quarter_centroid,
                                              receiver.normal, receiver.area_m2,
                                              receiver.diameter_m, 0.25 * near_d2)
                 : -1.0;
  if (f < 0.0) f = point_polygon_form_factor(source_centroid, source_normal, receiver.polygon);
  return f;
}

double patch_pair_form_factor(const Patch& source, const Patch& receiver, double far_ratio) {
  return patch_pair_form_factor(source.centroid, source.normal, receiver,
                                far_ratio * receiver.diameter_m * far_ratio * receiver.diameter_m);
}

ClusteredTransfer clustered_transfer(const PatchMesh& mesh, int room, double far_ratio,
                                     bool renormalise, size_t max_link_bytes,
                                     const geometry::Visibility* visibility) {
  ClusteredTransfer T;
  T.begin = mesh.room_begin[room];
  T.n = mesh.room_begin[room + 1] - T.begin;
  // The quality's opening, or a wider one where its links would not fit kMaxClusteredLinkBytes
  // (about kStoredBytesPerPatchOpening2 / opening^2 bytes per patch, with a fifth to spare):
  // reference on a hall of 250 000 patches would need ~2.7 GB at its 0.125.
  const double fit = std::sqrt(1.2 * kStoredBytesPerPatchOpening2 * static_cast<double>(T.n) /
                               static_cast<double>(max_link_bytes));
  T.opening = std::max(cluster_opening(far_ratio), fit);
  const double far = std::isfinite(far_ratio) ? far_ratio : kClusteredReferenceFarRatio;
  const size_t n = T.n;
  // Faces: runs of consecutive coplanar patches (the mesh lays each face out in one run).
  std::vector<uint32_t> idx(n);
  for (size_t k = 0; k < n; ++k) idx[k] = static_cast<uint32_t>(k);
  T.nodes.reserve(2 * n);
  for (size_t k = 0; k < n;) {
    const Patch& first = mesh.patches[T.begin + k];
    const double offset = glm::dot(first.normal, first.centroid);
    size_t e = k + 1;
    while (e < n && mesh.patches[T.begin + e].normal == first.normal &&
           std::abs(glm::dot(first.normal, mesh.patches[T.begin + e].centroid) - offset) <=
               kCoplanarDistance_m)
      ++e;
    T.roots.push_back(build_tree(mesh, T.begin, idx, k, e, T.nodes));
    k = e;
  }
  const size_t node_count = T.nodes.size();
  const SegmentEnds ends = visibility ? segment_ends(mesh, T.begin, T.nodes) : SegmentEnds{};

  // Receiver blocks: subtrees of at most kBlockPatches patches of each face's tree, with their
  // leaves and largest patch diameter.
  struct BlockRoot {
    uint32_t node = 0, face = 0;
    double max_diameter_m = 0.0;
  };
  std::vector<uint32_t> count(node_count, 0);  // patches under each node
  for (size_t a = node_count; a-- > 0;) {
    const ClusterNode& c = T.nodes[a];
    count[a] = is_leaf(c) ? 1 : count[c.child[0]] + count[c.child[1]];
  }
  std::vector<BlockRoot> block_roots;
  for (size_t f = 0; f < T.roots.size(); ++f) {
    std::vector<uint32_t> stack{T.roots[f]};
    while (!stack.empty()) {
      const uint32_t r = stack.back();
      stack.pop_back();
      if (count[r] > kBlockPatches) {
        stack.push_back(T.nodes[r].child[1]);
        stack.push_back(T.nodes[r].child[0]);
        continue;
      }
      BlockRoot root;
      ClusterBlock blk;
      root.node = r, root.face = uint32_t(f);
      std::vector<uint32_t> sub{r};
      while (!sub.empty()) {
        const uint32_t x = sub.back();
        sub.pop_back();
        const ClusterNode& c = T.nodes[x];
        if (is_leaf(c)) {
          blk.leaves.push_back(x);
          root.max_diameter_m = std::max(root.max_diameter_m, c.diameter_m);
        } else {
          sub.push_back(c.child[1]);
          sub.push_back(c.child[0]);
        }
      }
      block_roots.push_back(root);
      T.blocks.push_back(std::move(blk));
    }
  }

  // The interaction lists. A block first descends each other face's tree once for all its
  // patches: a node culled for the block's box is culled for each patch; one accepted for the box
  // (its diameter and the block's patches' below the opening ratio times the smallest distance,
  // each wholly in front of the other) is accepted by each patch and kept once for the block
  // (all bits of its ClusterBlock::whole_mask); one that no patch can accept (its diameter above
  // the opening ratio times the largest distance) is opened; the rest (and leaves) are where each
  // patch continues the descent by itself, into its own links. The links are those of a descent per
  // patch from the roots (Clustered.BlockSharedLinksAreThoseOfADescentPerPatch).
  const double opening2 = T.opening * T.opening;
  // In waves of kWaveBlocks blocks, the memory checked after each.
  size_t stored_bytes = 0;
  tbb::enumerable_thread_specific<std::vector<uint32_t>> own_masks;
  for (size_t wave = 0; wave < T.blocks.size(); wave += kWaveBlocks) {
    const size_t wave_end = std::min(T.blocks.size(), wave + kWaveBlocks);
    tbb::parallel_for(wave, wave_end, [&](size_t w) {
      const BlockRoot& root = block_roots[w];
      const ClusterNode& R = T.nodes[root.node];
      ClusterBlock& blk = T.blocks[w];
      // Source nodes to descend, each with whether the block sees all of it (proven by a shaft
      // verdict, or no visibility test) and the faces that may still block some of its segments
      // (those its parent's verdict left undecided: a node's shaft lies in its parent's, so no
      // other face can); then those left to each patch, likewise.
      struct Candidate {
        uint32_t node = 0;
        bool seen = false;
        geometry::ShaftFaces faces;
      };
      std::vector<Candidate> stack, candidates;
      std::vector<uint32_t> own_stack, distinct;
      // The nodes patches take by themselves (node, k: taken by blk.leaves[k]), and per patch its
      // links to single source patches.
      std::vector<std::pair<uint32_t, uint32_t>> own;
      const uint32_t all =
          blk.leaves.size() == 32 ? ~uint32_t(0) : (uint32_t(1) << blk.leaves.size()) - 1;
      std::vector<std::vector<std::pair<uint32_t, float>>> near(blk.leaves.size());
      for (size_t f = 0; f < T.roots.size(); ++f) {
        if (f == root.face) continue;  // a face does not light itself
        candidates.clear();
        stack.push_back({T.roots[f], visibility == nullptr, {}});
        while (!stack.empty()) {
          const Candidate top = stack.back();
          const uint32_t a_id = top.node;
          const bool seen = top.seen;
          stack.pop_back();
          const ClusterNode& a = T.nodes[a_id];
          if (!face_each_other(a, R)) continue;
          // Where the node would be linked (taken whole, or left to each patch), what the block
          // sees of it: hidden nodes are dropped, partly hidden ones opened (a leaf is left to each
          // patch's own segments), visible ones need no more segments below them.
          geometry::ShaftFaces undecided = top.faces;
          const auto verdict = [&] {
            return seen ? geometry::Shaft::visible
                        : node_verdict(*visibility, ends, T.nodes, a_id, root.node, top.faces,
                                       undecided);
          };
          if (is_leaf(a)) {
            const geometry::Shaft v = verdict();
            if (v != geometry::Shaft::hidden)
              candidates.push_back({a_id, v == geometry::Shaft::visible, undecided});
            continue;
          }
          const double dm = std::max(a.diameter_m, root.max_diameter_m);
          const Vec3 far_corner =
              glm::max(glm::abs(a.centroid - R.lo), glm::abs(a.centroid - R.hi));
          const bool whole =
              dm * dm < opening2 * geometry::box_distance2(a.centroid, R.lo, R.hi) &&
              box_min_height(a.normal, a.centroid, R.lo, R.hi) > -kFrontTolerance_m &&
              box_min_height(R.normal, R.centroid, a.lo, a.hi) > -kFrontTolerance_m;
          const bool open =
              !whole && a.diameter_m * a.diameter_m >= opening2 * glm::dot(far_corner, far_corner);
          const geometry::Shaft v = open ? geometry::Shaft::partial : verdict();
          if (v == geometry::Shaft::hidden) continue;
          if (v == geometry::Shaft::partial) {
            stack.push_back({a.child[0], seen, undecided});
            stack.push_back({a.child[1], seen, undecided});
            continue;
          }
          if (whole) {
            blk.whole_node.push_back(a_id);
            blk.whole_mask.push_back(all);
            continue;
          }
          candidates.push_back({a_id, true, {}});
        }
        for (size_t k = 0; k < blk.leaves.size(); ++k) {
          const ClusterNode& b = T.nodes[blk.leaves[k]];
          const Patch& dst = mesh.patches[T.begin + b.patch];
          for (const Candidate& cand : candidates) {
            const uint32_t c = cand.node;
            if (!cand.seen) {
              // A source patch partly hidden from the block: the dense path's factor times the
              // share of this patch its centroid sees (radiosity.cpp), its segments asking only
              // the faces the leaf's verdict against the block left undecided: the same answers.
              const ClusterNode& a = T.nodes[c];
              if (!face_each_other(a, b)) continue;
              double f = patch_pair_form_factor(mesh.patches[T.begin + a.patch], dst, far);
              if (f > 0.0)
                f *= visible_fraction_within(visibility, a.centroid + a.normal * kShootLift_m, dst,
                                             kShootLift_m, cand.faces);
              if (f > 0.0) near[k].push_back({c, static_cast<float>(f)});
              continue;
            }
            own_stack.push_back(c);
            while (!own_stack.empty()) {
              const uint32_t a_id = own_stack.back();
              own_stack.pop_back();
              const ClusterNode& a = T.nodes[a_id];
              if (!face_each_other(a, b)) continue;
              if (is_leaf(a)) {
                const double f = patch_pair_form_factor(mesh.patches[T.begin + a.patch], dst, far);
                if (f > 0.0) near[k].push_back({a_id, static_cast<float>(f)});
                continue;
              }
              // A source node is taken whole when it and the receiver are small against their
              // distance and each lies wholly in front of the other: the point kernel's error is
              // then of second order in the opening ratio (the first-order terms vanish at the
              // area-weighted centroid, for a node of uniform exitance).
              const Vec3 d = b.centroid - a.centroid;
              const double dm = std::max(a.diameter_m, b.diameter_m);
              if (dm * dm < opening2 * glm::dot(d, d) &&
                  box_min_height(a.normal, a.centroid, b.lo, b.hi) > -kFrontTolerance_m &&
                  box_min_height(b.normal, b.centroid, a.lo, a.hi) > -kFrontTolerance_m) {
                if (whole_node_factor(a, b) > 0.0) own.push_back({a_id, uint32_t(k)});
                continue;
              }
              own_stack.push_back(a.child[0]);
              own_stack.push_back(a.child[1]);
            }
          }
        }
      }
      // The own nodes merged into one entry per node, in node order: the masks gathered in a
      // per-thread array over the nodes (most nodes are taken by many of the block's patches,
      // so only the distinct ones are sorted), then cleared for the next block.
      std::vector<uint32_t>& own_mask = own_masks.local();
      own_mask.resize(node_count, 0);
      distinct.clear();
      for (const auto& [node, k] : own) {
        if (own_mask[node] == 0) distinct.push_back(node);
        own_mask[node] |= uint32_t(1) << k;
      }
      std::sort(distinct.begin(), distinct.end());
      for (const uint32_t node : distinct) {
        blk.whole_node.push_back(node);
        blk.whole_mask.push_back(own_mask[node]);
        own_mask[node] = 0;
      }
      blk.whole_node.shrink_to_fit();
      blk.whole_mask.shrink_to_fit();
      size_t near_count = 0;
      for (const auto& links : near) near_count += links.size();
      blk.near_begin.reserve(near.size() + 1);
      blk.near_source.reserve(near_count);
      blk.near_factor.reserve(near_count);
      blk.near_begin.push_back(0);
      for (const auto& links : near) {
        for (const auto& [source, factor] : links) {
          blk.near_source.push_back(source);
          blk.near_factor.push_back(factor);
        }
        blk.near_begin.push_back(static_cast<uint32_t>(blk.near_source.size()));
      }
    });
    for (size_t w = wave; w < wave_end; ++w) {
      const ClusterBlock& blk = T.blocks[w];
      stored_bytes += (blk.whole_node.size() + blk.whole_mask.size() + blk.near_source.size()) *
                          sizeof(uint32_t) +
                      blk.near_factor.size() * sizeof(float);
    }
    if (stored_bytes > max_link_bytes)
      throw CalculationError("indirect: room " + std::to_string(room) + " (" + std::to_string(n) +
                             " patches): the clustered transfer needs more than " +
                             std::to_string(max_link_bytes / kBytesPerMegabyte) +
                             " MB of links (limit)");
  }

  // Total factor per patch: its own links' and its ancestors' (the floats the sweeps use, in
  // double), and the count of links. Summed per fixed range of blocks, in range order below (the
  // same result on any number of threads), kSumWave ranges at a time in parallel.
  const size_t ranges = (T.blocks.size() + kSumBlocks - 1) / kSumBlocks;
  std::vector<double> total(node_count, 0.0);
  std::vector<std::vector<double>> partial(std::min(ranges, kSumWave));
  std::vector<size_t> partial_links(partial.size());
  for (size_t wave = 0; wave < ranges; wave += kSumWave) {
    const size_t wave_end = std::min(ranges, wave + kSumWave);
    tbb::parallel_for(wave, wave_end, [&](size_t r) {
      std::vector<double>& sum = partial[r - wave];
      sum.assign(node_count, 0.0);
      size_t links = 0;
      for (size_t w = r * kSumBlocks, e = std::min(T.blocks.size(), w + kSumBlocks); w < e; ++w) {
        const ClusterBlock& blk = T.blocks[w];
        const BlockLeaves leaves(blk, T.nodes);
        double f[kBlockPatches];
        for (size_t e = 0; e < blk.whole_node.size(); ++e) {
          leaves.factors(T.nodes[blk.whole_node[e]], blk.whole_mask[e], f);
          double s = 0.0;
          for (size_t k = 0; k < leaves.count; ++k) {
            s += f[k];
            links += f[k] > 0.0;
          }
          sum[blk.whole_node[e]] += s;
        }
        for (size_t l = 0; l < blk.near_source.size(); ++l)
          sum[blk.near_source[l]] += static_cast<double>(blk.near_factor[l]);
        links += blk.near_source.size();
      }
      partial_links[r - wave] = links;
    });
    for (size_t r = wave; r < wave_end; ++r) {
      const std::vector<double>& sum = partial[r - wave];
      for (size_t a = 0; a < node_count; ++a) total[a] += sum[a];
      T.link_count += partial_links[r - wave];
    }
  }
  std::vector<std::vector<double>>().swap(partial);
  for (size_t a = 0; a < node_count; ++a) {
    const ClusterNode& c = T.nodes[a];
    if (is_leaf(c)) continue;
    total[c.child[0]] += total[a];
    total[c.child[1]] += total[a];
  }
  T.source_scale.assign(n, 1.0);
  for (size_t a = 0; a < node_count; ++a) {
    const ClusterNode& c = T.nodes[a];
    if (!is_leaf(c)) continue;
    // As radiosity.cpp: the patches receive all but the share leaving through openings.
    const double kept = mesh.kept_fraction(T.begin + c.patch);
    T.max_row_correction = std::max(T.max_row_correction, std::abs(kept - total[a]));
    if (renormalise && total[a] > 0.0) T.source_scale[c.patch] = kept / total[a];
  }
  return T;
}

namespace {
// sweep_block (clustered.h), written once and compiled for the baseline and for AVX2
// (LUXGRID_MULTIVERSION): the loops over the block's patches are element by element, so four
// lanes give the bits of two (or one), and the sum over the nodes keeps its order.
LUXGRID_LANE void sweep_block_kernel(const ClusteredTransfer& T, size_t w, const double* flux,
                                     double* received) {
  const ClusterBlock& blk = T.blocks[w];
  const BlockLeaves leaves(blk, T.nodes);
  const size_t count = leaves.count;
  double sum[kBlockPatches] = {};
  double f[kBlockPatches];
  for (size_t e = 0; e < blk.whole_node.size(); ++e) {
    const double f_a = flux[blk.whole_node[e]];
    if (f_a == 0.0) continue;
    leaves.factors(T.nodes[blk.whole_node[e]], blk.whole_mask[e], f);
    for (size_t k = 0; k < count; ++k) sum[k] += f[k] * f_a;
  }
  for (size_t k = 0; k < count; ++k) {
    double s = sum[k];
    for (uint32_t l = blk.near_begin[k]; l < blk.near_begin[k + 1]; ++l)
      s += static_cast<double>(blk.near_factor[l]) * flux[blk.near_source[l]];
    received[T.nodes[blk.leaves[k]].patch] = s;
  }
}

}  // namespace

LUXGRID_MULTIVERSION(void, sweep_block,
                     (const ClusteredTransfer& T, size_t w, const double* flux, double* received),
                     (T, w, flux, received), sweep_block_kernel)

void apply_clustered(const ClusteredTransfer& T, const std::vector<double>& shot,
                     std::vector<double>& received, std::vector<double>& work) {
  const size_t m = T.nodes.size();
  work.resize(m);
  double* flux = work.data();  // per node: the scaled shot of its patches
  for (size_t a = m; a-- > 0;) {
    const ClusterNode& c = T.nodes[a];
    flux[a] =
        is_leaf(c) ? shot[c.patch] * T.source_scale[c.patch] : flux[c.child[0]] + flux[c.child[1]];
  }
  received.resize(T.n);
  tbb::parallel_for(size_t(0), T.blocks.size(),
                    [&](size_t w) { sweep_block(T, w, flux, received.data()); });
}

}  // namespace luxgrid::calc::indirect
