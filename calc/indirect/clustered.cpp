#include "calc/indirect/clustered.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>

#include <tbb/parallel_for.h>

#include "calc/indirect/form_factor.h"
#include "calc/indirect/limits.h"
#include "geometry/box3.h"
#include "util/error.h"

namespace luxgrid::calc::indirect {

using geometry::box_max_height;
using geometry::box_min_height;

namespace {
// As in radiosity.cpp: a receiver whose plane passes within this distance of the source point
// sees it edge-on; patches whose planes are this close (same normal) are coplanar.
constexpr double kMinPlaneDistance_m = 1e-9;
constexpr double kCoplanar_m = 1e-11;
// A node lies "wholly in front" of a plane when no vertex of its box is farther behind it than
// this (adjacent faces share an edge, at height 0 up to rounding).
constexpr double kFrontTolerance_m = 1e-9;
// Receiver subtrees of at most this many patches are refined as one parallel task: enough tasks
// to balance two to a few dozen threads, each large enough to amortise its start.
constexpr size_t kTaskPatches = 256;
// Blocks refined at a time before their links are appended (64 x 256 patches).
constexpr size_t kWaveBlocks = 64;
// Links per patch times opening^2, measured on the 100 x 50 x 6 m hall (300 links per patch at
// opening 0.4, 760 at 0.25): the count reserved before the lists are built.
constexpr double kLinksPerPatchOpening2 = 48.0;

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

}  // namespace

size_t ClusteredTransfer::bytes() const {
  return nodes.size() * sizeof(ClusterNode) + link_begin.size() * sizeof(uint64_t) +
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

double patch_pair_form_factor(const Patch& source, const Patch& receiver, double far_ratio) {
  const Vec3 d = receiver.centroid - source.centroid;  // source -> receiver
  const double h_dst = -glm::dot(receiver.normal, d);
  if (!(h_dst > kMinPlaneDistance_m)) return 0.0;
  const double h_src = glm::dot(source.normal, d);
  if (!(h_src > -receiver.diameter_m)) return 0.0;
  const double d2 = glm::dot(d, d);
  const double near_d2 = far_ratio * receiver.diameter_m * far_ratio * receiver.diameter_m;
  if (d2 > near_d2)
    return h_src > 0.0 ? receiver.area_m2 * point_kernel_pi_per_m2(h_src, h_dst, d2) / kPi : 0.0;
  double f = receiver.has_quarters
                 ? quarter_kernel_form_factor(source.centroid, source.normal, receiver.polygon,
                                              receiver.centroid, receiver.quarter_centroid,
                                              receiver.normal, receiver.area_m2,
                                              receiver.diameter_m, 0.25 * near_d2)
                 : -1.0;
  if (f < 0.0) f = point_polygon_form_factor(source.centroid, source.normal, receiver.polygon);
  return f;
}

ClusteredTransfer clustered_transfer(const PatchMesh& mesh, int room, double far_ratio,
                                     bool renormalise) {
  ClusteredTransfer T;
  T.begin = mesh.room_begin[room];
  T.n = mesh.room_begin[room + 1] - T.begin;
  T.opening = cluster_opening(far_ratio);
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
               kCoplanar_m)
      ++e;
    T.roots.push_back(build_tree(mesh, T.begin, idx, k, e, T.nodes));
    k = e;
  }
  const size_t node_count = T.nodes.size();

  // Which face each patch lies on, and its leaf.
  std::vector<uint32_t> face_of(n), leaf_of(n);
  for (size_t f = 0; f < T.roots.size(); ++f) {
    const uint32_t end = f + 1 < T.roots.size() ? T.roots[f + 1] : uint32_t(node_count);
    for (uint32_t a = T.roots[f]; a < end; ++a)
      if (is_leaf(T.nodes[a]))
        face_of[T.nodes[a].patch] = uint32_t(f), leaf_of[T.nodes[a].patch] = a;
  }

  // The interaction list of each receiving patch, blocks of kTaskPatches patches in parallel.
  const double opening2 = T.opening * T.opening;
  const size_t blocks = (n + kTaskPatches - 1) / kTaskPatches;
  std::vector<std::vector<Link>> block_links(kWaveBlocks);
  constexpr size_t kLinkBytes = sizeof(uint32_t) + sizeof(float);
  T.link_begin.assign(n + 1, 0);
  // Reserved at the expected count (kLinksPerPatchOpening2 / opening^2 per patch, plus a tenth):
  // growing by doubling copied the links several times (a tenth of the hall's run, with the page
  // faults of each new block).
  const size_t expected = static_cast<size_t>(1.1 * kLinksPerPatchOpening2 / opening2 * n);
  T.link_source.reserve(expected);
  T.link_factor.reserve(expected);
  // In waves of kWaveBlocks blocks, appended in patch order after each wave: the links are held
  // twice (per block and compressed) for one wave only.
  for (size_t wave = 0; wave < blocks; wave += kWaveBlocks) {
    const size_t wave_end = std::min(blocks, wave + kWaveBlocks);
    tbb::parallel_for(wave, wave_end, [&](size_t blk) {
      std::vector<Link>& out = block_links[blk - wave];
      std::vector<uint32_t> stack;
      for (size_t i = blk * kTaskPatches, i_end = std::min(n, i + kTaskPatches); i < i_end; ++i) {
        const ClusterNode& b = T.nodes[leaf_of[i]];
        const Patch& dst = mesh.patches[T.begin + i];
        for (size_t f = 0; f < T.roots.size(); ++f) {
          if (f == face_of[i]) continue;  // a face does not light itself
          stack.push_back(T.roots[f]);
          while (!stack.empty()) {
            const uint32_t a_id = stack.back();
            stack.pop_back();
            const ClusterNode& a = T.nodes[a_id];
            // One wholly on or behind the other's plane: every factor between them is 0.
            if (!(box_max_height(a.normal, a.centroid, b.lo, b.hi) > kMinPlaneDistance_m) ||
                !(box_max_height(b.normal, b.centroid, a.lo, a.hi) > kMinPlaneDistance_m))
              continue;
            if (is_leaf(a)) {
              const double f = patch_pair_form_factor(mesh.patches[T.begin + a.patch], dst, far);
              if (f > 0.0) out.push_back({uint32_t(i), a_id, static_cast<float>(f)});
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
                out.push_back({uint32_t(i), a_id, static_cast<float>(f)});
              }
              continue;
            }
            stack.push_back(a.child[0]);
            stack.push_back(a.child[1]);
          }
        }
      }
    });
    for (size_t blk = wave; blk < wave_end; ++blk) {
      std::vector<Link>& links = block_links[blk - wave];
      for (const Link& l : links) {
        ++T.link_begin[l.receiver + 1];
        T.link_source.push_back(l.source);
        T.link_factor.push_back(l.factor);
      }
      std::vector<Link>().swap(links);
    }
    if (T.link_source.size() * kLinkBytes > kMaxClusteredLinkBytes)
      throw CalculationError("indirect: room " + std::to_string(room) + " (" + std::to_string(n) +
                             " patches): the clustered transfer needs more than " +
                             std::to_string(kMaxClusteredLinkBytes / kBytesPerMegabyte) +
                             " MB of links (limit)");
  }
  for (size_t i = 0; i < n; ++i) T.link_begin[i + 1] += T.link_begin[i];
  if (T.link_source.capacity() > T.link_source.size() + T.link_source.size() / 4) {
    T.link_source.shrink_to_fit();
    T.link_factor.shrink_to_fit();
  }

  // Total factor per patch: its own links' and its ancestors' (the stored floats, in double).
  std::vector<double> total(node_count, 0.0);
  for (size_t k = 0; k < T.link_source.size(); ++k)
    total[T.link_source[k]] += static_cast<double>(T.link_factor[k]);
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
    T.max_row_correction = std::max(T.max_row_correction, std::abs(1.0 - total[a]));
    if (renormalise && total[a] > 0.0) T.source_scale[c.patch] = 1.0 / total[a];
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
    const uint64_t k0 = T.link_begin[i], k1 = T.link_begin[i + 1];
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
