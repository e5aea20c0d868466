#include "calc/indirect/clustered.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <tbb/parallel_for.h>

#include "calc/indirect/form_factor.h"
#include "calc/indirect/limits.h"
#include "geometry/box3.h"
#include "util/error.h"

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
constexpr size_t kWaveBlocks = 512;
// Links per patch times opening^2, measured on the 100 x 50 x 6 m hall (300 links per patch at
// opening 0.4, 760 at 0.25, 1 260 at 0.2): the count reserved before the lists are built.
constexpr double kLinksPerPatchOpening2 = 50.0;

struct Link {
  uint32_t receiver, source;
  float factor;
};

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

// Some part of each of the two clusters lies in front of the other's plane. If not, one is wholly
// on or behind the other's plane and every factor between their patches is 0.
bool face_each_other(const ClusterNode& a, const ClusterNode& b) {
  return box_max_height(a.normal, a.centroid, b.lo, b.hi) > kEdgeOnDistance_m &&
         box_max_height(b.normal, b.centroid, a.lo, a.hi) > kEdgeOnDistance_m;
}

}  // namespace

size_t ClusteredTransfer::bytes() const {
  return nodes.size() * sizeof(ClusterNode) + 2 * link_begin.size() * sizeof(uint64_t) +
         link_source.size() * (sizeof(uint32_t) + sizeof(float)) + n * sizeof(double);
}

bool use_clustered_transfer(const Room& room, double patch_size_m) {
  return outline_is_convex(room) && room.obstacles.empty() &&
         room_surface_area(room) / (patch_size_m * patch_size_m) >
             static_cast<double>(kClusteredAbovePatches);
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
                                     bool renormalise) {
  ClusteredTransfer T;
  T.begin = mesh.room_begin[room];
  T.n = mesh.room_begin[room + 1] - T.begin;
  // The quality's opening, or a wider one where its links would not fit kMaxClusteredLinkBytes
  // (about kLinksPerPatchOpening2 / opening^2 links per patch, with a fifth to spare): reference
  // on a hall of 250 000 patches would need ~3 200 links per patch at its 0.125.
  const double fit =
      std::sqrt(1.2 * kLinksPerPatchOpening2 * static_cast<double>(T.n) *
                (sizeof(uint32_t) + sizeof(float)) / static_cast<double>(kMaxClusteredLinkBytes));
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

  // Receiver blocks: subtrees of at most kBlockPatches patches of each face's tree, with their
  // patches and largest patch diameter.
  struct Block {
    uint32_t node = 0, face = 0;
    std::vector<uint32_t> patches;
    double max_diameter_m = 0.0;
  };
  std::vector<uint32_t> count(node_count, 0);  // patches under each node
  for (size_t a = node_count; a-- > 0;) {
    const ClusterNode& c = T.nodes[a];
    count[a] = is_leaf(c) ? 1 : count[c.child[0]] + count[c.child[1]];
  }
  std::vector<Block> blocks;
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
      Block blk;
      blk.node = r, blk.face = uint32_t(f);
      std::vector<uint32_t> sub{r};
      while (!sub.empty()) {
        const uint32_t x = sub.back();
        sub.pop_back();
        const ClusterNode& c = T.nodes[x];
        if (is_leaf(c)) {
          blk.patches.push_back(c.patch);
          blk.max_diameter_m = std::max(blk.max_diameter_m, c.diameter_m);
        } else {
          sub.push_back(c.child[1]);
          sub.push_back(c.child[0]);
        }
      }
      blocks.push_back(std::move(blk));
    }
  }
  std::vector<uint32_t> leaf_of(n);
  for (uint32_t a = 0; a < node_count; ++a)
    if (is_leaf(T.nodes[a])) leaf_of[T.nodes[a].patch] = a;

  // The interaction list of each receiving patch. A block first descends each other face's tree
  // once for all its patches: a node culled for the block's box is culled for each patch, one
  // accepted for the box (its diameter and the block's patches' below the opening ratio times
  // the smallest distance, each wholly in front of the other) is accepted by each patch, one
  // that no patch can accept (its diameter above the opening ratio times the largest distance)
  // is opened; the rest (and leaves) are where each patch continues the descent by itself. The
  // links are those of a descent per patch from the roots.
  const double opening2 = T.opening * T.opening;
  constexpr size_t kLinkBytes = sizeof(uint32_t) + sizeof(float);
  T.link_begin.assign(n, 0);
  T.link_end.assign(n, 0);
  // Reserved at the expected count (kLinksPerPatchOpening2 / opening^2 per patch, plus a tenth):
  // growing by doubling copied the links several times (a tenth of the hall's run, with the page
  // faults of each new block).
  const size_t expected = static_cast<size_t>(1.1 * kLinksPerPatchOpening2 / opening2 * n);
  T.link_source.reserve(expected);
  T.link_factor.reserve(expected);
  std::vector<std::vector<Link>> block_links(kWaveBlocks);
  // In waves of kWaveBlocks blocks, appended after each wave: the links are held twice (per block
  // and compressed) for one wave only.
  for (size_t wave = 0; wave < blocks.size(); wave += kWaveBlocks) {
    const size_t wave_end = std::min(blocks.size(), wave + kWaveBlocks);
    tbb::parallel_for(wave, wave_end, [&](size_t w) {
      const Block& blk = blocks[w];
      const ClusterNode& R = T.nodes[blk.node];
      std::vector<Link>& out = block_links[w - wave];
      std::vector<uint32_t> accepted, candidates, stack;
      // Per patch, grouped by patch: links of blk.patches[k] go to per_patch[k].
      std::vector<std::vector<Link>> per_patch(blk.patches.size());
      for (size_t f = 0; f < T.roots.size(); ++f) {
        if (f == blk.face) continue;  // a face does not light itself
        accepted.clear(), candidates.clear();
        stack.push_back(T.roots[f]);
        while (!stack.empty()) {
          const uint32_t a_id = stack.back();
          stack.pop_back();
          const ClusterNode& a = T.nodes[a_id];
          if (!face_each_other(a, R)) continue;
          if (is_leaf(a)) {
            candidates.push_back(a_id);
            continue;
          }
          const double dm = std::max(a.diameter_m, blk.max_diameter_m);
          if (dm * dm < opening2 * geometry::box_distance2(a.centroid, R.lo, R.hi) &&
              box_min_height(a.normal, a.centroid, R.lo, R.hi) > -kFrontTolerance_m &&
              box_min_height(R.normal, R.centroid, a.lo, a.hi) > -kFrontTolerance_m) {
            accepted.push_back(a_id);
            continue;
          }
          const Vec3 far_corner =
              glm::max(glm::abs(a.centroid - R.lo), glm::abs(a.centroid - R.hi));
          if (a.diameter_m * a.diameter_m >= opening2 * glm::dot(far_corner, far_corner)) {
            stack.push_back(a.child[0]);
            stack.push_back(a.child[1]);
            continue;
          }
          candidates.push_back(a_id);
        }
        for (size_t k = 0; k < blk.patches.size(); ++k) {
          const uint32_t i = blk.patches[k];
          const ClusterNode& b = T.nodes[leaf_of[i]];
          const Patch& dst = mesh.patches[T.begin + i];
          std::vector<Link>& mine = per_patch[k];
          for (const uint32_t a_id : accepted) {
            const ClusterNode& a = T.nodes[a_id];
            if (!(box_max_height(a.normal, a.centroid, b.lo, b.hi) > kEdgeOnDistance_m)) continue;
            const Vec3 d = b.centroid - a.centroid;
            const double h_src = glm::dot(a.normal, d), h_dst = -glm::dot(b.normal, d);
            if (h_src > 0.0 && h_dst > 0.0) {
              const double f =
                  b.area_m2 * point_kernel_pi_per_m2(h_src, h_dst, glm::dot(d, d)) / kPi;
              mine.push_back({i, a_id, static_cast<float>(f)});
            }
          }
          for (const uint32_t c : candidates) {
            stack.push_back(c);
            while (!stack.empty()) {
              const uint32_t a_id = stack.back();
              stack.pop_back();
              const ClusterNode& a = T.nodes[a_id];
              if (!face_each_other(a, b)) continue;
              if (is_leaf(a)) {
                const double f = patch_pair_form_factor(mesh.patches[T.begin + a.patch], dst, far);
                if (f > 0.0) mine.push_back({i, a_id, static_cast<float>(f)});
                continue;
              }
              // A source node is taken whole when it and the receiver are small against their
              // distance and each lies wholly in front of the other: the point kernel's error is
              // then of second order in the opening ratio (the first-order terms vanish at the
              // area-weighted centroid, for a node of uniform exitance).
              const Vec3 d = b.centroid - a.centroid;
              const double d2 = glm::dot(d, d);
              const double dm = std::max(a.diameter_m, b.diameter_m);
              if (dm * dm < opening2 * d2 &&
                  box_min_height(a.normal, a.centroid, b.lo, b.hi) > -kFrontTolerance_m &&
                  box_min_height(b.normal, b.centroid, a.lo, a.hi) > -kFrontTolerance_m) {
                const double h_src = glm::dot(a.normal, d), h_dst = -glm::dot(b.normal, d);
                if (h_src > 0.0 && h_dst > 0.0) {
                  const double f = b.area_m2 * point_kernel_pi_per_m2(h_src, h_dst, d2) / kPi;
                  mine.push_back({i, a_id, static_cast<float>(f)});
                }
                continue;
              }
              stack.push_back(a.child[0]);
              stack.push_back(a.child[1]);
            }
          }
        }
      }
      for (auto& mine : per_patch) out.insert(out.end(), mine.begin(), mine.end());
    });
    // Appended in block order, each block copied in parallel at its offset.
    std::vector<size_t> offset(wave_end - wave + 1, T.link_source.size());
    for (size_t w = wave; w < wave_end; ++w)
      offset[w - wave + 1] = offset[w - wave] + block_links[w - wave].size();
    T.link_source.resize(offset.back());
    T.link_factor.resize(offset.back());
    tbb::parallel_for(wave, wave_end, [&](size_t w) {
      std::vector<Link>& links = block_links[w - wave];
      const size_t o = offset[w - wave];
      for (size_t k = 0; k < links.size(); ++k) {
        const Link& l = links[k];
        if (k == 0 || l.receiver != links[k - 1].receiver) T.link_begin[l.receiver] = o + k;
        T.link_source[o + k] = l.source;
        T.link_factor[o + k] = l.factor;
        T.link_end[l.receiver] = o + k + 1;
      }
      std::vector<Link>().swap(links);
    });
    if (T.link_source.size() * kLinkBytes > kMaxClusteredLinkBytes)
      throw CalculationError("indirect: room " + std::to_string(room) + " (" + std::to_string(n) +
                             " patches): the clustered transfer needs more than " +
                             std::to_string(kMaxClusteredLinkBytes / kBytesPerMegabyte) +
                             " MB of links (limit)");
  }
  if (T.link_source.capacity() > T.link_source.size() + T.link_source.size() / 4) {
    T.link_source.shrink_to_fit();
    T.link_factor.shrink_to_fit();
  }

  // Total factor per patch: its own links' and its ancestors' (the stored floats, in double).
  // Summed per fixed range of links (in range order below: the same result on any number of
  // threads), in parallel.
  constexpr size_t kSumRange = size_t(1) << 22;
  const size_t ranges = (T.link_source.size() + kSumRange - 1) / kSumRange;
  std::vector<std::vector<double>> partial(ranges);
  tbb::parallel_for(size_t(0), ranges, [&](size_t r) {
    partial[r].assign(node_count, 0.0);
    for (size_t k = r * kSumRange, e = std::min(T.link_source.size(), k + kSumRange); k < e; ++k)
      partial[r][T.link_source[k]] += static_cast<double>(T.link_factor[k]);
  });
  std::vector<double> total(node_count, 0.0);
  for (const auto& p : partial)
    for (size_t a = 0; a < node_count; ++a) total[a] += p[a];
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
  tbb::parallel_for(size_t(0), T.n, [&](size_t i) {
    const uint64_t k0 = T.link_begin[i], k1 = T.link_end[i];
    double s0 = 0.0, s1 = 0.0;
    uint64_t k = k0;
    for (; k + 2 <= k1; k += 2) {
      s0 += static_cast<double>(T.link_factor[k]) * flux[T.link_source[k]];
      s1 += static_cast<double>(T.link_factor[k + 1]) * flux[T.link_source[k + 1]];
    }
    if (k < k1) s0 += static_cast<double>(T.link_factor[k]) * flux[T.link_source[k]];
    received[i] = s0 + s1;
  });
}

}  // namespace luxgrid::calc::indirect
