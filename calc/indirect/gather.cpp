#include "calc/indirect/gather.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

#include "calc/indirect/chunk_verdict.h"
#include "calc/indirect/far_kernels.h"
#include "calc/indirect/form_factor.h"
#include "calc/indirect/partial_visibility.h"
#include "geometry/box3.h"
#include "geometry/shaft.h"

namespace luxgrid::calc::indirect {

using geometry::box_distance2;
using geometry::box_max_height;
using geometry::box_min_height;

GatherSet make_gather_set(const PatchMesh& mesh, size_t begin, size_t end,
                          const std::vector<double>& exitant_flux_lm, double far_ratio,
                          const SubcellExitance* cells, double cluster_opening) {
  GatherSet set;
  set.cluster_opening = cluster_opening;
  // Runs of emitting patches in one plane. Not the same normal alone: a receiver skips a whole
  // group unless it is in front of every patch of it (gather_set_point), so two parallel faces in
  // one group (the floor and a cabinet's top, consecutive once the walls between them emit
  // nothing, as with one bounce) would hide the floor from every point below the top's plane.
  std::vector<std::pair<size_t, size_t>> runs;  // [first, last) into `emitting`
  std::vector<size_t> emitting;
  const auto offset = [&](size_t j) {
    return glm::dot(mesh.patches[j].normal, mesh.patches[j].centroid);
  };
  for (size_t j = begin; j < end; ++j) {
    if (!(exitant_flux_lm[j] > 0.0)) continue;
    if (emitting.empty() || mesh.patches[emitting.back()].normal != mesh.patches[j].normal ||
        std::abs(offset(j) - offset(emitting[runs.back().first])) > kGatherCoplanar_m)
      runs.push_back({emitting.size(), emitting.size()});
    emitting.push_back(j);
    runs.back().second = emitting.size();
  }
  for (const auto& [first, last] : runs) {
    GatherSet::Group g;
    g.normal = mesh.patches[emitting[first]].normal;
    g.max_offset = -std::numeric_limits<double>::infinity();
    g.begin = set.chunks.size();
    Vec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    double dmax = 0.0;
    for (size_t k = first; k < last; ++k) {
      const Patch& p = mesh.patches[emitting[k]];
      lo = glm::min(lo, p.centroid), hi = glm::max(hi, p.centroid);
      dmax = std::max(dmax, p.diameter_m);
      g.max_offset = std::max(g.max_offset, glm::dot(p.normal, p.centroid));
    }
    // Tiles of kChunkTile x the largest diameter: sort the run by tile (stable, so the order
    // within a tile is the mesh's).
    const double tile = std::max(kChunkTile * dmax, 1e-9);
    // Clustered rooms: the tiles ordered by block (kBlockChunks tiles a side) first, so that a
    // block's chunks are consecutive; otherwise the block key is 0 and the order the tiles'.
    const double block = cluster_opening > 0.0 ? kBlockChunks * tile : 0.0;
    auto key = [&](size_t j) {
      const Vec3 t = glm::floor((mesh.patches[j].centroid - lo) / tile);
      const Vec3 b = block > 0.0 ? glm::floor((mesh.patches[j].centroid - lo) / block) : Vec3(0.0);
      return std::array<double, 6>{b.x, b.y, b.z, t.x, t.y, t.z};
    };
    std::vector<size_t> order(emitting.begin() + first, emitting.begin() + last);
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return key(a) < key(b); });
    for (size_t k = 0; k < order.size(); ++k) {
      if (k == 0 || key(order[k]) != key(order[k - 1])) {
        GatherSet::Chunk c;
        c.begin = c.end = set.patch.size();
        c.lo = c.clo = Vec3(std::numeric_limits<double>::infinity());
        c.hi = c.chi = Vec3(-std::numeric_limits<double>::infinity());
        set.chunks.push_back(c);
      }
      const size_t j = order[k];
      const Patch& p = mesh.patches[j];
      GatherSet::Chunk& c = set.chunks.back();
      const double limit = far_ratio * p.diameter_m;
      set.cx.push_back(p.centroid.x);
      set.cy.push_back(p.centroid.y);
      set.cz.push_back(p.centroid.z);
      set.flux_lm.push_back(exitant_flux_lm[j]);
      set.near_d2.push_back(limit * limit);
      set.patch.push_back(j);
      const long first = cells && !cells->first.empty() ? cells->first[j] : -1;
      set.first_cell.push_back(first < 0 ? -1 : static_cast<long>(set.cell_exitance_lm_m2.size()));
      if (first >= 0) {
        const auto* m = cells->exitance_lm_m2.data() + first;
        set.cell_exitance_lm_m2.insert(set.cell_exitance_lm_m2.end(), m,
                                       m + kSubcellsPerSide * kSubcellsPerSide);
      }
      c.end = set.patch.size();
      c.clo = glm::min(c.clo, p.centroid), c.chi = glm::max(c.chi, p.centroid);
      for (const auto& v : p.polygon) c.lo = glm::min(c.lo, v), c.hi = glm::max(c.hi, v);
      c.max_near_d2 = std::max(c.max_near_d2, limit * limit);
      c.max_diameter_m = std::max(c.max_diameter_m, p.diameter_m);
      c.flux_lm += exitant_flux_lm[j];
      c.flux_centroid += exitant_flux_lm[j] * p.centroid;
    }
    for (size_t c = g.begin; c < set.chunks.size(); ++c) {
      GatherSet::Chunk& ch = set.chunks[c];
      ch.flux_centroid /= ch.flux_lm;  // every entry has flux > 0
      ch.diagonal2_m2 = glm::dot(ch.hi - ch.lo, ch.hi - ch.lo);
    }
    g.block_begin = g.block_end = set.blocks.size();
    if (block > 0.0) {
      std::array<double, 6> previous{};
      for (size_t c = g.begin; c < set.chunks.size(); ++c) {
        const GatherSet::Chunk& ch = set.chunks[c];
        const auto k = key(set.patch[ch.begin]);
        if (c == g.begin || k[0] != previous[0] || k[1] != previous[1] || k[2] != previous[2]) {
          GatherSet::Chunk b;
          b.begin = b.end = c;
          b.lo = b.clo = Vec3(std::numeric_limits<double>::infinity());
          b.hi = b.chi = Vec3(-std::numeric_limits<double>::infinity());
          set.blocks.push_back(b);
        }
        previous = k;
        GatherSet::Chunk& b = set.blocks.back();
        b.end = c + 1;
        b.lo = glm::min(b.lo, ch.lo), b.hi = glm::max(b.hi, ch.hi);
        b.clo = glm::min(b.clo, ch.clo), b.chi = glm::max(b.chi, ch.chi);
        b.max_near_d2 = std::max(b.max_near_d2, ch.max_near_d2);
        b.max_diameter_m = std::max(b.max_diameter_m, ch.max_diameter_m);
        b.flux_lm += ch.flux_lm;
        b.flux_centroid += ch.flux_lm * ch.flux_centroid;
      }
      for (size_t b = g.block_begin; b < set.blocks.size(); ++b) {
        GatherSet::Chunk& bl = set.blocks[b];
        bl.flux_centroid /= bl.flux_lm;
        bl.diagonal2_m2 = glm::dot(bl.hi - bl.lo, bl.hi - bl.lo);
      }
      g.block_end = set.blocks.size();
    }
    g.end = set.chunks.size();
    set.groups.push_back(g);
  }
  return set;
}

namespace {

// Entries of a chunk whose far kernels are computed at once (far_terms).
constexpr size_t kTermBlock = 32;

// Form factor from the point (x, n) to patch p in the final gather: the point kernel when the
// patch is far (`far`: beyond far_ratio x its diameter), the kernel on its quarters between
// far_ratio x D / 2 and far_ratio x D, Lambert's exact polygon formula closer (and whenever the
// quarter rule declines: non-parallelogram patches, patches crossing the horizon).
double gather_form_factor(const Vec3& x, const Vec3& n, const Patch& p, double far_ratio,
                          bool far) {
  if (far) return point_kernel_form_factor(x, n, p.centroid, p.normal, p.area_m2);
  const double half = 0.5 * far_ratio * p.diameter_m;
  const double f = p.has_quarters
                       ? quarter_kernel_form_factor(x, n, p.polygon, p.centroid, p.quarter_centroid,
                                                    p.normal, p.area_m2, p.diameter_m, half * half)
                       : -1.0;
  return f < 0.0 ? point_polygon_form_factor(x, n, p.polygon) : f;
}

// E at (x, n) from the kSubcellsPerSide^2 cells of a refined patch, each with its own exitance:
// per cell, its point kernel beyond far_ratio x its diameter, Lambert's polygon formula closer.
double gather_cells(const Vec3& x, const Vec3& n, const Patch& p, const double* cell_exitance_lm_m2,
                    double far_ratio) {
  const double cell_diameter = p.diameter_m / kSubcellsPerSide;
  const double cell_area = p.area_m2 / (kSubcellsPerSide * kSubcellsPerSide);
  const double near_d2 = far_ratio * far_ratio * cell_diameter * cell_diameter;
  double e = 0.0;
  for (int a = 0; a < kSubcellsPerSide; ++a)
    for (int b = 0; b < kSubcellsPerSide; ++b) {
      const double m = cell_exitance_lm_m2[a * kSubcellsPerSide + b];
      if (!(m > 0.0)) continue;
      const SubcellCorners cell = subcell_corners(p, a, b);
      const Vec3 centre = 0.25 * (cell[0] + cell[1] + cell[2] + cell[3]);
      e += m * subcell_form_factor(x, n, p, cell, centre, cell_area, near_d2);
    }
  return e;
}

}  // namespace

double gather_set_point(const PatchMesh& mesh, const GatherSet& set, const Vec3& x, const Vec3& n,
                        double far_ratio, const geometry::Visibility* visibility,
                        const GatherBand& band) {
  const double inner2 = band.inner_m * band.inner_m, outer2 = band.outer_m * band.outer_m;
  double near = 0.0, far = 0.0;
  const double* cx = set.cx.data();
  const double* cy = set.cy.data();
  const double* cz = set.cz.data();
  const double* flux = set.flux_lm.data();
  const double opening2 = set.cluster_opening * set.cluster_opening;
  for (const auto& g : set.groups) {
    // x behind (or on) the group's plane (one plane, make_gather_set): every term is 0.
    if (!(glm::dot(g.normal, x) - g.max_offset > kGatherPlaneDistance_m)) continue;
    const Vec3 m = g.normal;
    // A chunk, or a block of chunks, as one source at its flux centroid: when it is seen under
    // less than the opening ratio, its height over the receiver's plane varies by less than that
    // ratio (a wall chunk seen from a workplane point) and it lies wholly inside the band. Adds
    // its light to `far` and says so. The caller has checked that nothing occludes, that the
    // receiver is in front of it and that it is beyond its near distance.
    const auto as_one_source = [&](const GatherSet::Chunk& c) {
      if (!(opening2 > 0.0 && c.diagonal2_m2 < opening2 * box_distance2(x, c.lo, c.hi)))
        return false;
      const Vec3 far_corner = glm::max(glm::abs(x - c.clo), glm::abs(x - c.chi));
      const Vec3 dx = x - c.flux_centroid;
      if (!(box_max_height(n, x, c.lo, c.hi) - box_min_height(n, x, c.lo, c.hi) <
                set.cluster_opening * -glm::dot(n, dx) &&
            box_distance2(x, c.clo, c.chi) >= inner2 && glm::dot(far_corner, far_corner) < outer2))
        return false;
      far += c.flux_lm * point_kernel_at(dx.x, dx.y, dx.z, m, n);
      return true;
    };
    // Blocks of chunks (clustered rooms): a far block seen under less than the opening ratio is
    // one source; otherwise its chunks, as below. Without blocks: one range, every chunk.
    const bool by_block = g.block_end > g.block_begin;
    for (size_t b = g.block_begin; b < (by_block ? g.block_end : g.block_begin + 1); ++b) {
      size_t c_begin = g.begin, c_end = g.end;
      if (by_block) {
        const GatherSet::Chunk& bl = set.blocks[b];
        c_begin = bl.begin, c_end = bl.end;
        if (box_max_height(n, x, bl.lo, bl.hi) < 0.0) continue;
        if (!visibility && box_min_height(n, x, bl.clo, bl.chi) > 0.0 &&
            box_distance2(x, bl.clo, bl.chi) > bl.max_near_d2 && as_one_source(bl))
          continue;
      }
      for (size_t c = c_begin; c < c_end; ++c) {
        const GatherSet::Chunk& ch = set.chunks[c];
        // Every vertex behind the receiver's tangent plane: so are the centroids and quarter
        // centroids, and the kernel and the horizon-clipped polygon give 0.
        if (box_max_height(n, x, ch.lo, ch.hi) < 0.0) continue;
        if (!(box_distance2(x, ch.clo, ch.chi) < outer2)) continue;
        if (!visibility && box_min_height(n, x, ch.clo, ch.chi) > 0.0 &&
            box_distance2(x, ch.clo, ch.chi) > ch.max_near_d2) {
          // Far kernel for the whole chunk: every centroid in front of the receiver (n . dx < 0),
          // the receiver in front of every patch (group test), farther than its near distance.
          if (as_one_source(ch)) continue;
          double sum = 0.0;
          for (size_t k = ch.begin; k < ch.end; k += kTermBlock) {
            const size_t count = std::min(kTermBlock, ch.end - k);
            double terms[kTermBlock];
            far_terms(cx + k, cy + k, cz + k, flux + k, count, x, n, m, inner2, outer2, terms);
            for (size_t q = 0; q < count; ++q) sum += terms[q];
          }
          far += sum;
          continue;
        }
        // The chunk's shaft verdict from the receiver (chunk_verdict.h): every sample point of its
        // patches, lifted off their face, lies in the chunk's vertex box moved by the lift.
        NarrowingChunkVerdict verdict(
            visibility != nullptr, [&, from = x + n * kGatherLift_m](geometry::ShaftFaces& faces) {
              std::array<Vec3, 8> corners;
              const size_t count = geometry::box_element(ch.lo, ch.hi, m * kGatherLift_m, corners);
              return visibility->classify_within(std::span<const Vec3>(&from, 1),
                                                 std::span<const Vec3>(corners.data(), count),
                                                 geometry::ShaftFaces{}, faces);
            });
        for (size_t k = ch.begin; k < ch.end; ++k) {
          const Vec3 dx = x - Vec3(cx[k], cy[k], cz[k]);
          const double hm = glm::dot(m, dx);
          if (!(hm > kGatherPlaneDistance_m)) continue;
          const double d2 = glm::dot(dx, dx);
          if (d2 < inner2 || !(d2 < outer2)) continue;
          if (d2 > set.near_d2[k] && !visibility) {
            // The far kernel of one entry, as far_terms evaluates it (point_kernel_at): flux x
            // the kernel, the pi once, below; the receiver must see the centroid.
            if (-glm::dot(n, dx) > 0.0) far += flux[k] * point_kernel_at(dx.x, dx.y, dx.z, m, n);
            continue;
          }
          const Patch& p = mesh.patches[set.patch[k]];
          if (set.first_cell[k] >= 0 &&
              d2 < kSubcellReach * kSubcellReach * p.diameter_m * p.diameter_m) {
            const double* cells = &set.cell_exitance_lm_m2[set.first_cell[k]];
            double e = gather_cells(x, n, p, cells, far_ratio);
            const geometry::Shaft seen = e > 0.0 ? verdict.ask() : geometry::Shaft::visible;
            if (seen == geometry::Shaft::hidden) continue;
            // The chunk leaves it undecided: its own verdict, then cell by cell where a shadow
            // edge crosses it (partial_visibility.h).
            if (seen == geometry::Shaft::partial)
              e = undecided_patch_integral(x, n, x + n * kGatherLift_m, p, cells, 0.0, e, far_ratio,
                                           *visibility, kGatherLift_m, verdict.faces());
            near += e;
            continue;
          }
          double f = gather_form_factor(x, n, p, far_ratio, d2 > set.near_d2[k]);
          const geometry::Shaft seen = f > 0.0 ? verdict.ask() : geometry::Shaft::visible;
          if (seen == geometry::Shaft::hidden) continue;
          if (seen == geometry::Shaft::partial) {
            const Vec3 from = x + n * kGatherLift_m;
            if (p.has_quarters) {
              const double exitance = flux[k] / p.area_m2;
              near +=
                  undecided_patch_integral(x, n, from, p, nullptr, exitance, exitance * f,
                                           far_ratio, *visibility, kGatherLift_m, verdict.faces());
              continue;
            }
            f *= visible_fraction(visibility, from, p, kGatherLift_m);
          }
          near += flux[k] / p.area_m2 * f;
        }
      }
    }
  }
  return near + far / kPi;
}

void mark_near_patches(const PatchMesh& mesh, const GatherSet& set, const Vec3& x, const Vec3& n,
                       std::vector<std::atomic<char>>& near) {
  for (const auto& g : set.groups) {
    if (!(glm::dot(g.normal, x) - g.max_offset > kGatherPlaneDistance_m)) continue;
    for (size_t c = g.begin; c < g.end; ++c) {
      const GatherSet::Chunk& ch = set.chunks[c];
      const double reach = kSubcellReach * ch.max_diameter_m;
      if (box_max_height(n, x, ch.lo, ch.hi) < 0.0 ||
          box_distance2(x, ch.clo, ch.chi) > reach * reach)
        continue;
      for (size_t k = ch.begin; k < ch.end; ++k) {
        const Patch& p = mesh.patches[set.patch[k]];
        const Vec3 d = x - p.centroid;
        if (glm::dot(g.normal, d) > kGatherPlaneDistance_m &&
            glm::dot(d, d) < kSubcellReach * kSubcellReach * p.diameter_m * p.diameter_m)
          near[set.patch[k]].store(1, std::memory_order_relaxed);
      }
    }
  }
}

}  // namespace luxgrid::calc::indirect
