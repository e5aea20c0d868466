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
  return 1.0 / (std::isfinite(far_ratio) ? far_ratio : kClusteredReferenceFarRatio);
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

  // Receiver tasks: subtrees of at most kTaskPatches patches (their ancestors receive no links).
  std::vector<uint32_t> count(node_count, 0);  // patches under each node
  for (size_t b = node_count; b-- > 0;) {
    const ClusterNode& c = T.nodes[b];
    count[b] = is_leaf(c) ? 1 : count[c.child[0]] + count[c.child[1]];
  }
  std::vector<std::pair<uint32_t, size_t>> tasks;  // receiver subtree root, its face
  for (size_t f = 0; f < T.roots.size(); ++f) {
    std::vector<uint32_t> stack{T.roots[f]};
    while (!stack.empty()) {
      const uint32_t b = stack.back();
      stack.pop_back();
      if (count[b] <= kTaskPatches) {
        tasks.push_back({b, f});
        continue;
      }
      stack.push_back(T.nodes[b].child[0]);
      stack.push_back(T.nodes[b].child[1]);
    }
  }

  const double opening2 = T.opening * T.opening;
  std::vector<std::vector<Link>> task_links(tasks.size());
  std::atomic<size_t> total_links{0};
  std::atomic<bool> over{false};
  constexpr size_t kLinkBytes = sizeof(uint32_t) + sizeof(float);
  tbb::parallel_for(size_t(0), tasks.size(), [&](size_t t) {
    if (over.load(std::memory_order_relaxed)) return;
    std::vector<Link>& out = task_links[t];
    std::vector<std::pair<uint32_t, uint32_t>> stack;
    for (size_t f = 0; f < T.roots.size(); ++f) {
      if (f == tasks[t].second) continue;  // a face does not light itself
      stack.push_back({T.roots[f], tasks[t].first});
      while (!stack.empty()) {
        const auto [a_id, b_id] = stack.back();
        stack.pop_back();
        const ClusterNode& a = T.nodes[a_id];
        const ClusterNode& b = T.nodes[b_id];
        // One node wholly on or behind the other's plane: every factor between them is 0.
        if (!(box_max_height(a.normal, a.centroid, b.lo, b.hi) > kMinPlaneDistance_m) ||
            !(box_max_height(b.normal, b.centroid, a.lo, a.hi) > kMinPlaneDistance_m))
          continue;
        const bool a_leaf = is_leaf(a), b_leaf = is_leaf(b);
        if (a_leaf && b_leaf) {
          const double f = patch_pair_form_factor(mesh.patches[T.begin + a.patch],
                                                  mesh.patches[T.begin + b.patch], far);
          if (f > 0.0) out.push_back({b_id, a_id, static_cast<float>(f)});
          continue;
        }
        const Vec3 d = b.centroid - a.centroid;
        const double d2 = glm::dot(d, d);
        const double dm = std::max(a.diameter_m, b.diameter_m);
        if (dm * dm < opening2 * d2 &&
            box_min_height(a.normal, a.centroid, b.lo, b.hi) > -kFrontTolerance_m &&
            box_min_height(b.normal, b.centroid, a.lo, a.hi) > -kFrontTolerance_m) {
          const double h_src = glm::dot(a.normal, d), h_dst = -glm::dot(b.normal, d);
          if (h_src > 0.0 && h_dst > 0.0) {
            const double f = b.area_m2 * point_kernel_pi_per_m2(h_src, h_dst, d2) / kPi;
            out.push_back({b_id, a_id, static_cast<float>(f)});
          }
          continue;
        }
        if (!a_leaf && (b_leaf || a.diameter_m >= b.diameter_m)) {
          stack.push_back({a.child[0], b_id});
          stack.push_back({a.child[1], b_id});
        } else {
          stack.push_back({a_id, b.child[0]});
          stack.push_back({a_id, b.child[1]});
        }
      }
    }
    const size_t total = total_links.fetch_add(out.size()) + out.size();
    if (total * kLinkBytes > kMaxClusteredLinkBytes) over.store(true);
  });
  if (over.load())
    throw CalculationError("indirect: room " + std::to_string(room) + " (" + std::to_string(n) +
                           " patches): the clustered transfer needs more than " +
                           std::to_string(kMaxClusteredLinkBytes / kBytesPerMegabyte) +
                           " MB of links (limit)");

  // Compressed rows by receiver node.
  T.link_begin.assign(node_count + 1, 0);
  for (const auto& links : task_links)
    for (const Link& l : links) ++T.link_begin[l.receiver + 1];
  for (size_t b = 0; b < node_count; ++b) T.link_begin[b + 1] += T.link_begin[b];
  T.link_source.resize(T.link_begin[node_count]);
  T.link_factor.resize(T.link_begin[node_count]);
  {
    std::vector<uint64_t> fill(T.link_begin.begin(), T.link_begin.end() - 1);
    for (auto& links : task_links) {
      for (const Link& l : links) {
        const uint64_t k = fill[l.receiver]++;
        T.link_source[k] = l.source;
        T.link_factor[k] = l.factor;
      }
      std::vector<Link>().swap(links);
    }
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
  work.assign(2 * m, 0.0);
  double* flux = work.data();     // per node: the scaled shot of its patches
  double* irr = work.data() + m;  // per node: incident flux / area, then pushed down
  for (size_t a = m; a-- > 0;) {
    const ClusterNode& c = T.nodes[a];
    flux[a] =
        is_leaf(c) ? shot[c.patch] * T.source_scale[c.patch] : flux[c.child[0]] + flux[c.child[1]];
  }
  tbb::parallel_for(size_t(0), m, [&](size_t b) {
    const uint64_t k0 = T.link_begin[b], k1 = T.link_begin[b + 1];
    if (k0 == k1) return;
    double s0 = 0.0, s1 = 0.0;
    uint64_t k = k0;
    for (; k + 2 <= k1; k += 2) {
      s0 += static_cast<double>(T.link_factor[k]) * flux[T.link_source[k]];
      s1 += static_cast<double>(T.link_factor[k + 1]) * flux[T.link_source[k + 1]];
    }
    if (k < k1) s0 += static_cast<double>(T.link_factor[k]) * flux[T.link_source[k]];
    irr[b] = (s0 + s1) / T.nodes[b].area_m2;
  });
  received.assign(T.n, 0.0);
  for (size_t a = 0; a < m; ++a) {
    const ClusterNode& c = T.nodes[a];
    if (is_leaf(c)) {
      received[c.patch] = irr[a] * c.area_m2;
      continue;
    }
    irr[c.child[0]] += irr[a];
    irr[c.child[1]] += irr[a];
  }
}

}  // namespace luxgrid::calc::indirect
