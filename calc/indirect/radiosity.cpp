#include "calc/indirect/radiosity.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "calc/indirect/chunk_verdict.h"
#include "calc/indirect/far_kernels.h"
#include "geometry/shaft.h"
#include "util/error.h"

namespace luxgrid::calc::indirect {

using geometry::box_distance2;
using geometry::box_max_height;
using geometry::box_min_height;

namespace {
// The geometric tail is added once the bounce ratio has changed by less than this (relative)
// over the last sweep; below it the tail's shape error is negligible against the tolerances.
constexpr double kRatioStability = 1e-4;
constexpr int kMinSweepsBeforeTail = 4;
// A bounce ratio this close to 1 is no absorption up to rounding (reflectance 1 everywhere: the
// form factors' rows sum to 1 only to rounding, so the ratio lands a few units in the last place
// either side of 1). The series does not converge, and a geometric tail r / (1 - r) there would
// multiply rounding by 1e9 and more and call the result converged.
constexpr double kNoAbsorptionRatio = 1.0 - 1e-9;

double l1(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += std::abs(x);
  return s;
}

// Tile size of the source chunks, in units of the largest patch diameter of a coplanar run.
constexpr double kSourceChunkTile = 4.0;

// Sources of a chunk whose far form factors are computed at once (far_form_factors).
constexpr size_t kFarBlock = 32;

}  // namespace

FormFactorMatrix form_factors(const PatchMesh& mesh, int room,
                              const geometry::Visibility* visibility, double far_ratio,
                              bool renormalise) {
  FormFactorMatrix F;
  F.begin = mesh.room_begin[room];
  F.n = mesh.room_begin[room + 1] - F.begin;
  F.renormalised = renormalise;
  const size_t n = F.n;
  if (n > kMaxPatchesPerRoom)
    throw CalculationError("indirect: room " + std::to_string(room) + " has " + std::to_string(n) +
                           " patches; its form-factor matrix would take " +
                           std::to_string(sizeof(float) * n * n / kBytesPerMegabyte) +
                           " MB, above the limit of " +
                           std::to_string(kMaxFormFactorMatrixBytes / kBytesPerMegabyte) + " MB (" +
                           std::to_string(kMaxPatchesPerRoom) + " patches)");
  // Centroids and normals side by side: the inner loop below streams through them n^2 times.
  std::vector<Vec3> centroid(n), normal(n);
  for (size_t k = 0; k < n; ++k) {
    centroid[k] = mesh.patches[F.begin + k].centroid;
    normal[k] = mesh.patches[F.begin + k].normal;
  }
  // Runs of consecutive coplanar patches (same normal, same plane): their mutual entries are 0
  // (the plane test below rejects them), so they are neither computed nor read by the sweeps.
  F.zero_begin.assign(n, 0);
  F.zero_end.assign(n, 0);
  for (size_t k = 0; k < n;) {
    size_t e = k + 1;
    const double offset = glm::dot(normal[k], centroid[k]);
    while (e < n && normal[e] == normal[k] &&
           std::abs(glm::dot(normal[e], centroid[e]) - offset) <= kCoplanarDistance_m)
      ++e;
    for (size_t q = k; q < e; ++q) F.zero_begin[q] = k, F.zero_end[q] = e;
    k = e;
  }
  // The sources of each coplanar run in tiles (chunks) of kSourceChunkTile x the run's largest
  // diameter: a receiver takes a chunk that is wholly far, wholly in front of it and with it
  // wholly in front of the chunk's plane in one loop without branches (most of the matrix).
  struct Chunk {
    size_t begin = 0, end = 0;  // into `order`
    size_t run = 0;             // first patch of the coplanar run
    Vec3 normal{0.0};
    double max_offset = 0.0;  // largest normal . centroid
    Vec3 lo{0.0}, hi{0.0};    // bounding box of the centroids
  };
  std::vector<size_t> order;
  std::vector<double> ox, oy, oz;
  std::vector<Chunk> chunks;
  for (size_t k = 0; k < n; k = F.zero_end[k]) {
    const size_t e = F.zero_end[k];
    Vec3 lo = centroid[k], hi = centroid[k];
    double dmax = 0.0;
    for (size_t q = k; q < e; ++q) {
      lo = glm::min(lo, centroid[q]), hi = glm::max(hi, centroid[q]);
      dmax = std::max(dmax, mesh.patches[F.begin + q].diameter_m);
    }
    const double tile = std::max(kSourceChunkTile * dmax, 1e-9);
    auto key = [&](size_t q) {
      const Vec3 t = glm::floor((centroid[q] - lo) / tile);
      return std::array<double, 3>{t.x, t.y, t.z};
    };
    std::vector<size_t> run(e - k);
    for (size_t q = k; q < e; ++q) run[q - k] = q;
    std::stable_sort(run.begin(), run.end(), [&](size_t a, size_t b) { return key(a) < key(b); });
    for (size_t r = 0; r < run.size(); ++r) {
      const size_t q = run[r];
      if (r == 0 || key(q) != key(run[r - 1])) {
        Chunk c;
        c.begin = c.end = order.size();
        c.run = k;
        c.normal = normal[q];
        c.max_offset = -std::numeric_limits<double>::infinity();
        c.lo = c.hi = centroid[q];
        chunks.push_back(c);
      }
      Chunk& c = chunks.back();
      order.push_back(q);
      ox.push_back(centroid[q].x), oy.push_back(centroid[q].y), oz.push_back(centroid[q].z);
      c.end = order.size();
      c.max_offset = std::max(c.max_offset, glm::dot(normal[q], centroid[q]));
      c.lo = glm::min(c.lo, centroid[q]), c.hi = glm::max(c.hi, centroid[q]);
    }
  }
  // Filled one receiving row at a time (row i = F[j -> i] over all sources j), so every write
  // lands in one row (in cache); the per-source sums needed for the renormalisation are column
  // sums, taken after.
  F.allocate_gather();  // not zeroed here: each row is cleared below
  // Fixed blocks of rows, each adding its rows into its own partial column sums (summed in block
  // order below: the same result on any number of threads), so the sums need no second pass
  // over the matrix.
  constexpr size_t kRowBlock = 64;
  const size_t blocks = (n + kRowBlock - 1) / kRowBlock;
  std::vector<double> partial(blocks * n, 0.0);
  tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
    double* psum = partial.data() + b * n;
    for (size_t i = b * kRowBlock, i_end = std::min(n, i + kRowBlock); i < i_end; ++i) {
      const Patch& dst = mesh.patches[F.begin + i];
      const Vec3 dc = dst.centroid, dn = dst.normal;
      const double near_d2 = far_ratio * dst.diameter_m * far_ratio * dst.diameter_m;
      const double area_m2 = dst.area_m2;
      float* row = F.gather.data() + i * n;
      // The receiver's sample points' element (visible_fraction lifts them off its face).
      std::vector<Vec3> receiver;
      if (visibility)
        for (const Vec3& v : dst.polygon) receiver.push_back(v + dn * kShootLift_m);
      std::fill(row, row + n, 0.0f);
      for (const Chunk& c : chunks) {
        if (c.run == F.zero_begin[i]) continue;  // coplanar with i: zeros
        // Every source's height over the receiver's plane at most kEdgeOnDistance_m: all 0.
        if (!(box_max_height(dn, dc, c.lo, c.hi) > kEdgeOnDistance_m)) continue;
        const Vec3 sn = c.normal;
        if (!visibility && box_min_height(dn, dc, c.lo, c.hi) > kEdgeOnDistance_m &&
            glm::dot(sn, dc) - c.max_offset > 0.0 && box_distance2(dc, c.lo, c.hi) > near_d2) {
          // All far, h_dst > kEdgeOnDistance_m and h_src > 0: the kernel for every source.
          for (size_t k = c.begin; k < c.end; k += kFarBlock) {
            const size_t count = std::min(kFarBlock, c.end - k);
            double terms[kFarBlock];
            far_form_factors(ox.data() + k, oy.data() + k, oz.data() + k, count, dc, dn, sn,
                             area_m2, terms);
            for (size_t q = 0; q < count; ++q) row[order[k + q]] = static_cast<float>(terms[q]);
          }
          continue;
        }
        // The chunk's shaft verdict against the receiver (chunk_verdict.h): each source's
        // shooting point lies in its centroid box moved by the lift, the receiver's sample points
        // in its polygon moved by the lift (visible_fraction).
        // Where it is partial, each source's segments ask only the faces it left undecided
        // (geometry/narrowed_visibility.h): the same answers.
        geometry::ShaftFaces chunk_faces;
        ChunkVerdict verdict(visibility != nullptr, [&] {
          std::array<Vec3, 8> sources;
          const size_t count = geometry::box_element(c.lo, c.hi, sn * kShootLift_m, sources);
          return visibility->classify_within(
              std::span<const Vec3>(sources.data(), count),
              std::span<const Vec3>(receiver.data(), receiver.size()), geometry::ShaftFaces{},
              chunk_faces);
        });
        for (size_t k = c.begin; k < c.end; ++k) {
          const size_t j = order[k];
          if (i == j) continue;
          const Vec3 sc = centroid[j];
          double f = patch_pair_form_factor(sc, sn, dst, near_d2);
          const geometry::Shaft seen = f > 0.0 ? verdict.ask() : geometry::Shaft::visible;
          if (seen == geometry::Shaft::hidden)
            f = 0.0;
          else if (seen == geometry::Shaft::partial)
            f *= visible_fraction_within(visibility, sc + sn * kShootLift_m, dst, kShootLift_m,
                                         chunk_faces);
          row[j] = static_cast<float>(f);
        }
      }
      for (size_t j = 0; j < n; ++j) psum[j] += row[j];
    }
  });
  // Per-source sums (columns) of the stored floats, in double, and the renormalisation.
  std::vector<double> sum(n, 0.0);
  for (size_t b = 0; b < blocks; ++b)
    for (size_t j = 0; j < n; ++j) sum[j] += partial[b * n + j];
  F.source_scale.assign(n, 1.0);
  for (size_t j = 0; j < n; ++j) {
    // What the patches should receive: all of the source's light in a closed room, less the
    // share leaving through openings (patches.h).
    const double kept = mesh.kept_fraction(F.begin + j);
    F.max_row_correction = std::max(F.max_row_correction, std::abs(kept - sum[j]));
    if (renormalise && sum[j] > 0.0) F.source_scale[j] = kept / sum[j];
  }
  return F;
}

RadiosityResult solve_radiosity(const FormFactorMatrix& F, const std::vector<double>& reflectance,
                                const std::vector<double>& incident_flux_lm, int bounces,
                                double tolerance, int max_bounces) {
  const size_t n = F.n;
  std::vector<double> shot(n);  // delta x the per-source renormalisation
  const auto transfer = [&](const std::vector<double>& delta, std::vector<double>& received) {
    for (size_t j = 0; j < n; ++j)
      shot[j] = F.source_scale.empty() ? delta[j] : delta[j] * F.source_scale[j];
    tbb::parallel_for(size_t(0), n, [&](size_t i) {
      const float* row = F.gather.data() + i * n;
      // Entries [zero_begin, zero_end) are 0 (coplanar patches): skipped.
      const size_t zb = F.zero_begin.empty() ? n : F.zero_begin[i];
      const size_t ze = F.zero_begin.empty() ? n : F.zero_end[i];
      received[i] = row_dot(row, shot.data(), 0, zb) + row_dot(row, shot.data(), ze, n);
    });
  };
  return solve_bounce_series(n, transfer, reflectance, incident_flux_lm, bounces, tolerance,
                             max_bounces);
}

RadiosityResult solve_radiosity(const ClusteredTransfer& T, const std::vector<double>& reflectance,
                                const std::vector<double>& incident_flux_lm, int bounces,
                                double tolerance, int max_bounces) {
  std::vector<double> work;
  const auto transfer = [&](const std::vector<double>& delta, std::vector<double>& received) {
    apply_clustered(T, delta, received, work);
  };
  return solve_bounce_series(T.n, transfer, reflectance, incident_flux_lm, bounces, tolerance,
                             max_bounces);
}

RadiosityResult solve_bounce_series(size_t n, const BounceTransfer& transfer,
                                    const std::vector<double>& reflectance,
                                    const std::vector<double>& incident_flux_lm, int bounces,
                                    double tolerance, int max_bounces) {
  if (bounces > kMaxBounces || max_bounces > kMaxBounces)
    throw CalculationError("indirect: " + std::to_string(std::max(bounces, max_bounces)) +
                           " bounces requested, at most " + std::to_string(kMaxBounces));
  RadiosityResult res;
  std::vector<double> delta(n), next(n);
  for (size_t i = 0; i < n; ++i) delta[i] = reflectance[i] * incident_flux_lm[i];
  res.exitant_flux_lm = delta;
  res.bounces_run = 1;
  double delta_norm = l1(delta);
  res.bounce_flux_lm.push_back(delta_norm);
  double total = delta_norm;
  if (n == 0 || total == 0.0) return res;

  std::vector<double> received(n);
  auto sweep = [&]() {
    transfer(delta, received);
    for (size_t i = 0; i < n; ++i) next[i] = reflectance[i] * received[i];
    delta.swap(next);
    for (size_t i = 0; i < n; ++i) res.exitant_flux_lm[i] += delta[i];
    const double prev_norm = delta_norm;
    delta_norm = l1(delta);
    res.bounce_flux_lm.push_back(delta_norm);
    total += delta_norm;
    ++res.bounces_run;
    return prev_norm > 0.0 ? delta_norm / prev_norm : 0.0;
  };

  const int target = bounces > 0 ? bounces : max_bounces;
  double ratio_prev = std::numeric_limits<double>::quiet_NaN();
  while (res.bounces_run < target) {
    const double r = sweep();
    if (bounces > 0) continue;
    if (!(r < kNoAbsorptionRatio)) {  // no absorption: the series does not converge
      ratio_prev = r;
      continue;
    }
    const double tail = delta_norm * r / (1.0 - r);
    if (tail <= tolerance * total) {
      res.residual = tail / total;
      return res;
    }
    const int sweeps = res.bounces_run - 1;
    if (sweeps >= kMinSweepsBeforeTail && std::abs(r - ratio_prev) <= kRatioStability * r) {
      // Geometric remainder, distributed like the last bounce (the dominant eigenvector).
      const double factor = r / (1.0 - r);
      for (size_t i = 0; i < n; ++i) res.exitant_flux_lm[i] += delta[i] * factor;
      res.tail_added = true;
      // Error of the tail: the ratio may still drift by |r - r_prev| per sweep.
      res.residual =
          delta_norm * std::abs(r - ratio_prev) / ((1.0 - r) * (1.0 - r)) / (total + tail);
      return res;
    }
    ratio_prev = r;
  }
  // Fixed N (or the cap): the light not followed is roughly the next bounces' share.
  if (res.bounce_flux_lm.size() >= 2) {
    const double prev = res.bounce_flux_lm[res.bounce_flux_lm.size() - 2];
    // A bounce's flux underflows to 0 after some 700 reflections at reflectance 0.3 (0.3^700 is
    // below the smallest double): nothing is left to follow, the remainder is 0, not 0 / 0.
    const double r = prev > 0.0 ? res.bounce_flux_lm.back() / prev : 0.0;
    res.residual =
        r < 1.0 ? delta_norm * r / (1.0 - r) / total : std::numeric_limits<double>::infinity();
  } else {
    // One bounce: estimate the next bounce from the mean reflectance (flux-weighted).
    double rho = 0.0;
    for (size_t i = 0; i < n; ++i) rho += reflectance[i] * delta[i];
    rho /= total;
    res.residual = rho < 1.0 ? rho / (1.0 - rho) : std::numeric_limits<double>::infinity();
  }
  return res;
}

}  // namespace luxgrid::calc::indirect
