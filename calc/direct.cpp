#include "calc/direct.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <mutex>
#include <optional>
#include <span>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "calc/nearfield/far_run.h"
#include "calc/nearfield/models.h"
#include "calc/nearfield/switch_run.h"
#include "calc/nearfield/table_rung_scratch.h"
#include "geometry/pair_visibility.h"
#include "photometry/distribution_texture.h"
#include "util/simd.h"

namespace luxgrid::calc {

nearfield::Receiver receiver_of(geometry::Quantity q, const Vec3& normal) {
  switch (q) {
    case geometry::Quantity::cylindrical: return nearfield::Receiver::cylindrical();
    case geometry::Quantity::semi_cylindrical: return nearfield::Receiver::semi_cylindrical(normal);
    default: return nearfield::Receiver::planar(normal);
  }
}

namespace {

// E_direct of the points [begin, end) of one zone when every pair is the far-field point model
// on a plane without a visibility test (near_field "never", draft): luminaires outside, points
// inside, each point's sum over the luminaires in the zone's order (the same sums as the
// general loop, added in the same order). A texture is looked up without the virtual call.
LUXGRID_LANE void far_field_run_kernel(const std::vector<nearfield::Emitter>& emitters,
                                       const std::vector<uint32_t>& luminaires,
                                       const geometry::SurfaceGrid& grid, size_t begin, size_t end,
                                       std::vector<double>& E) {
  // The run's active points packed once (the luminaires then read contiguous arrays).
  Vec3 point[kFarFieldRun], normal[kFarFieldRun];
  size_t index[kFarFieldRun];
  size_t n = 0;
  for (size_t i = begin; i < end; ++i) {
    if (!grid.active.empty() && !grid.active[i]) continue;
    point[n] = grid.points[i], normal[n] = grid.normals[i], index[n] = i;
    ++n;
  }
  double sum[kFarFieldRun] = {};
  // The texture's lookups of a run at once (structure of arrays): the pairs' geometry first, then
  // the batch lookup, then the sums: point_source_illuminance_with's two steps (nearfield::
  // far_pair, far_pair_illuminance) on the same values, so the same sums to the last bit.
  double lx[kFarFieldRun], ly[kFarFieldRun], lz[kFarFieldRun], weight[kFarFieldRun],
      d2[kFarFieldRun], cd[kFarFieldRun];
  for (const uint32_t k : luminaires) {
    const nearfield::Emitter& e = emitters[k];
    if (e.far_texture) {
      for (size_t q = 0; q < n; ++q) {
        const nearfield::FarPair pair =
            nearfield::far_pair(e.centroid, point[q], nearfield::Receiver::planar(normal[q]));
        d2[q] = pair.d2, weight[q] = pair.weight;
        const Vec3 local = e.world_to_local * -pair.r;
        lx[q] = local.x, ly[q] = local.y, lz[q] = local.z;
      }
      e.far_texture->bilinear_batch(lx, ly, lz, static_cast<int>(n), cd);
      const double factor = e.far_texture_factor;
      // Adding 0 where the pair gives nothing leaves the sum's bits as they are (it is >= +0),
      // and keeps the loop free of branches.
      for (size_t q = 0; q < n; ++q) {
        const double lux = nearfield::far_pair_illuminance(factor * cd[q], weight[q], d2[q]);
        sum[q] += nearfield::far_pair_lit(d2[q], weight[q]) ? lux : 0.0;
      }
    } else {
      const photometry::IntensityDistribution& d = e.far_lookup();
      for (size_t q = 0; q < n; ++q)
        sum[q] += nearfield::point_source_illuminance_with(
            [&](const Vec3& local, double inv_length) { return d.intensity(local * inv_length); },
            e.world_to_local, e.centroid, point[q], nearfield::Receiver::planar(normal[q]));
    }
  }
  for (size_t k = 0; k < n; ++k) E[index[k]] = sum[k];
}

}  // namespace

LUXGRID_MULTIVERSION(void, far_field_run,
                     (const std::vector<nearfield::Emitter>& emitters,
                      const std::vector<uint32_t>& luminaires, const geometry::SurfaceGrid& grid,
                      size_t begin, size_t end, std::vector<double>& E),
                     (emitters, luminaires, grid, begin, end, E), far_field_run_kernel)

double far_field_illuminance(const Luminaire& lum, const Vec3& point, const Vec3& normal) {
  // The rotation is orthonormal, so world -> luminaire frame is its transpose.
  return nearfield::point_source_illuminance(*lum.distribution, glm::transpose(lum.pose.rotation),
                                             lum.pose.position, point,
                                             nearfield::Receiver::planar(normal));
}

std::vector<nearfield::Emitter> make_emitters(const Scene& scene) {
  std::vector<nearfield::Emitter> out;
  out.reserve(scene.luminaires.size());
  // The table rung's cells depend on the table alone: built for the first luminaire of each
  // distribution and shared by the others (a hall's 1000 luminaires share one table).
  std::map<const photometry::IntensityDistribution*,
           std::shared_ptr<const nearfield::TableGammaCells>>
      cells;
  for (const auto& l : scene.luminaires) {
    const auto known = cells.find(l.distribution.get());
    out.push_back(nearfield::make_emitter(l.opening, l.pose.position, l.pose.rotation,
                                          l.distribution, nearfield::kDefaultDiskSegments,
                                          known == cells.end() ? nullptr : known->second));
    if (known == cells.end()) cells.emplace(l.distribution.get(), out.back().table_cells);
  }
  return out;
}

std::vector<double> direct_illuminance(const Plan& plan,
                                       const std::vector<nearfield::Emitter>& emitters,
                                       const geometry::SurfaceGrid& grid, const Progress& progress,
                                       DirectCounts* counts, const GridReach* reach,
                                       std::vector<double>* estimated_error_lx) {
  std::vector<double> E(grid.points.size(), 0.0);
  if (estimated_error_lx) estimated_error_lx->assign(grid.points.size(), 0.0);
  std::atomic<size_t> done{0};
  std::mutex count_mutex;
  const size_t total = grid.points.size();
  // Per zone its luminaires and its visibility test (nullptr when nothing can occlude: the
  // near-field models then skip every test). Without `reach` one zone: every luminaire, the
  // plan's test.
  struct Zone {
    std::vector<uint32_t> all;  // used when no reach is given
    const std::vector<uint32_t>* luminaires = nullptr;
    const geometry::Visibility* visibility = nullptr;
    std::vector<const nearfield::Emitter*> emitters;  // the luminaires' emitters, in order
  };
  std::vector<Zone> zones(reach ? reach->reach.zone_count() : 1);
  for (size_t z = 0; z < zones.size(); ++z) {
    zones[z].visibility = plan.visibility_test.get();
    if (reach) {
      const ReachZone& rz = reach->reach.zone(static_cast<uint32_t>(z));
      zones[z].luminaires = &rz.luminaires;
      zones[z].visibility = rz.visibility.get();
    } else {
      zones[z].all.resize(emitters.size());
      for (uint32_t k = 0; k < emitters.size(); ++k) zones[z].all[k] = k;
      zones[z].luminaires = &zones[z].all;
    }
    for (const uint32_t k : *zones[z].luminaires) zones[z].emitters.push_back(&emitters[k]);
  }
  // The automatic switch's weights of a point's pairs, computed for all its luminaires at once
  // (nearfield/switch_run.h: the same weights as pair by pair).
  const bool automatic = plan.near_switch == nearfield::NearFieldSwitch::automatic;
  // Far field everywhere on planes, nothing to occlude: the run loop (far_field_run).
  const bool planar = grid.quantity != geometry::Quantity::cylindrical &&
                      grid.quantity != geometry::Quantity::semi_cylindrical;
  const bool far_runs = plan.near_switch == nearfield::NearFieldSwitch::never && planar &&
                        std::all_of(zones.begin(), zones.end(),
                                    [](const Zone& z) { return z.visibility == nullptr; });
  tbb::parallel_for(tbb::blocked_range<size_t>(0, total, 16), [&](const auto& range) {
    DirectCounts local;
    // The table rung's buffers, grown on the chunk's first pairs and reused by the rest.
    nearfield::TableRungScratch scratch;
    std::vector<nearfield::SwitchWeights> weights;
    std::vector<const nearfield::Emitter*> far_emitters;
    std::vector<double> far_lux;
    if (far_runs) {
      for (size_t begin = range.begin(); begin != range.end();) {
        const uint32_t zone = reach ? reach->zone_of_point[begin] : 0;
        size_t end = begin + 1;
        while (end != range.end() && end - begin < kFarFieldRun &&
               (!reach || reach->zone_of_point[end] == zone))
          ++end;
        const std::vector<uint32_t>& luminaires = *zones[zone].luminaires;
        far_field_run(emitters, luminaires, grid, begin, end, E);
        if (counts) {
          size_t points = 0, active = 0;
          for (const uint32_t k : luminaires) points += emitters[k].is_point() ? 1 : 0;
          for (size_t i = begin; i < end; ++i) active += grid.active.empty() || grid.active[i];
          local.point_sources += active * points;
          local.far += active * (luminaires.size() - points);
        }
        begin = end;
      }
    }
    for (size_t i = far_runs ? range.end() : range.begin(); i != range.end(); ++i) {
      if (!grid.active.empty() && !grid.active[i]) continue;
      double sum = 0.0, error_lx = 0.0;
      const nearfield::Receiver receiver = receiver_of(grid.quantity, grid.normals[i]);
      const Zone& zone = zones[reach ? reach->zone_of_point[i] : 0];
      const geometry::Visibility* visibility = zone.visibility;
      // Without a visibility test on a plane, the pairs beyond their blend band are the far
      // field alone: looked up together (nearfield/far_run.h: the same values pair by pair).
      const bool far_together = automatic && !visibility && planar;
      if (automatic) {
        weights.resize(zone.emitters.size());
        nearfield::switch_weights_run(zone.emitters.data(), zone.emitters.size(), grid.points[i],
                                      weights.data());
      }
      if (far_together) {
        far_emitters.clear();
        for (size_t j = 0; j < zone.emitters.size(); ++j)
          if (weights[j].far >= 1.0) far_emitters.push_back(zone.emitters[j]);
        far_lux.resize(far_emitters.size());
        nearfield::far_field_pairs(far_emitters.data(), far_emitters.size(), grid.points[i],
                                   grid.normals[i], far_lux.data());
      }
      size_t next_far = 0;
      for (size_t j = 0; j < zone.emitters.size(); ++j) {
        const nearfield::Emitter& emitter = *zone.emitters[j];
        // Soft shadows: the near-field models test visibility per node, the far field from
        // the opening's centre.
        nearfield::SwitchWeights w;
        // The pair's shaft verdict serves its quadrature nodes (geometry/pair_visibility.h).
        const std::span<const Vec3> opening = emitter.vertices.empty()
                                                  ? std::span<const Vec3>(&emitter.centroid, 1)
                                                  : std::span<const Vec3>(emitter.vertices);
        const std::optional<geometry::PairVisibility> shaft =
            visibility ? std::make_optional<geometry::PairVisibility>(
                             *visibility, opening, std::span<const Vec3>(&grid.points[i], 1))
                       : std::nullopt;
        const geometry::Visibility* occluder = shaft ? &*shaft : nullptr;
        // A far pair's weights as hybrid_illuminance_weighted would pass them on (its `fixed` is
        // read only where the far weight is below 1).
        const bool far_pair = far_together && weights[j].far >= 1.0;
        if (far_pair) w = weights[j];
        const double pair =
            far_pair ? far_lux[next_far++]
            : automatic
                ? nearfield::hybrid_illuminance_weighted(emitter, grid.points[i], receiver,
                                                         plan.near_model, weights[j], occluder, &w,
                                                         &scratch)
                : nearfield::hybrid_illuminance(emitter, grid.points[i], receiver, plan.near_model,
                                                plan.near_switch, occluder, &w, &scratch);
        sum += pair;
        if (estimated_error_lx) error_lx += pair * nearfield::estimated_pair_error(emitter, w);
        if (!counts) continue;
        if (emitter.is_point()) {
          ++local.point_sources;
        } else {
          (w.far >= 1.0 ? local.far : w.far <= 0.0 ? local.near : local.blended) += 1;
          if (w.far < 1.0 && w.fixed >= 1.0) ++local.fixed_rule;
          if (w.far < 1.0 && w.fixed > 0.0 && w.fixed < 1.0) ++local.fixed_blended;
        }
      }
      E[i] = sum;
      if (estimated_error_lx) (*estimated_error_lx)[i] = error_lx;
    }
    if (counts) {
      std::lock_guard lock(count_mutex);
      *counts += local;
    }
    const size_t now = done += range.size();
    if (progress) progress(static_cast<double>(now) / static_cast<double>(total));
  });
  return E;
}

}  // namespace luxgrid::calc
