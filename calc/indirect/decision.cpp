#include "calc/indirect/decision.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>

#include "calc/direct.h"
#include "calc/indirect/emitter_cells.h"
#include "calc/indirect/patches.h"
#include "calc/scaled_distribution.h"
#include "geometry/polygon.h"

namespace luxgrid::calc::indirect {

namespace {
// Auto-mode estimate of the direct light: at most this many far-field points per surface.
constexpr size_t kDecisionSamplesPerSurface = 256;

// Area-weighted mean reflectance of a room's faces (floor, ceiling, walls).
double mean_reflectance(const Room& room) {
  const double a_floor = std::abs(geometry::signed_area(room.outline));
  const double a_walls = geometry::perimeter(room.outline) * room.height;
  const double a = 2.0 * a_floor + a_walls;
  if (!(a > 0.0)) return 0.0;
  return (a_floor * (room.reflectance.floor + room.reflectance.ceiling) +
          a_walls * room.reflectance.walls) /
         a;
}

}  // namespace

IndirectDecision decide_indirect(const Scene& scene) {
  IndirectDecision d;
  if (scene.settings.indirect == IndirectMode::off) {
    d.reason = IndirectReason::off_in_settings;
    return d;
  }
  bool any = false;
  for (const auto& r : scene.rooms) {
    any = any || r.reflectance.floor > 0.0 || r.reflectance.walls > 0.0 ||
          r.reflectance.ceiling > 0.0;
    for (const auto& o : r.obstacles) any = any || o.reflectance > 0.0;
  }
  if (!any) {
    d.reason = IndirectReason::no_reflectance;
    return d;
  }
  if (scene.luminaires.empty()) {
    d.reason = IndirectReason::no_luminaires;
    return d;
  }
  // Integrating-sphere estimate per room: rho Phi / (A (1 - rho)), rho area-weighted.
  // luminous_flux integrates the whole distribution: once per distinct one.
  // Phi is the flux entering the room: the part of each opening inside it (emitter_cells.h).
  std::map<const photometry::IntensityDistribution*, double>& flux_of = d.luminous_flux_lm;
  std::vector<double> room_flux_lm(scene.rooms.size(), 0.0);
  for (const auto& lum : scene.luminaires)
    for (const RoomCells& part : emitter_cells(scene, lum)) {
      auto [it, fresh] = flux_of.try_emplace(lum.distribution.get(), 0.0);
      if (fresh) it->second = luminous_flux(*lum.distribution);
      room_flux_lm[part.room] += part.weight * it->second;
    }
  for (size_t r = 0; r < scene.rooms.size(); ++r) {
    const Room& room = scene.rooms[r];
    const double flux = room_flux_lm[r];
    const double rho = mean_reflectance(room);
    const double area = room_surface_area(room);
    const double e = rho < 1.0 && area > 0.0 ? rho * flux / (area * (1.0 - rho))
                                             : std::numeric_limits<double>::infinity();
    d.estimate_lx = std::max(d.estimate_lx, e);
  }
  if (scene.settings.indirect == IndirectMode::on) {
    d.run = true;
    d.reason = IndirectReason::forced_on;
    return d;
  }
  // UGR's background luminance is the indirect illuminance at the eye (calc/glare/ugr.h): with
  // an observers surface reflected light is never skipped as small.
  for (const auto& s : scene.surfaces) {
    if (s.kind != geometry::SurfaceGrid::Kind::observers) continue;
    d.run = true;
    d.reason = IndirectReason::observers;
    d.observers_surface = s.name;
    return d;
  }
  // Mean direct light on the calculation surfaces, far field, on a sample of points.
  // The sample points first, then their illuminances in parallel, summed in order.
  std::vector<std::pair<const geometry::SurfaceGrid*, size_t>> samples;
  for (const auto& s : scene.surfaces) {
    const size_t step = std::max<size_t>(1, s.points.size() / kDecisionSamplesPerSurface);
    for (size_t i = 0; i < s.points.size(); i += step) {
      if (!s.active.empty() && !s.active[i]) continue;
      samples.push_back({&s, i});
    }
  }
  std::vector<double> sample_e(samples.size(), 0.0);
  tbb::parallel_for(size_t(0), samples.size(), [&](size_t k) {
    const auto& [s, i] = samples[k];
    double e = 0.0;
    for (const auto& lum : scene.luminaires)
      e += far_field_illuminance(lum, s->points[i], s->normals[i]);
    sample_e[k] = e;
  });
  double sum = 0.0;
  for (double e : sample_e) sum += e;
  const size_t count = samples.size();
  d.mean_direct_lx = count ? sum / count : 0.0;
  d.sampled = count > 0;
  if (count > 0 && d.estimate_lx < kAutoSkipFraction * d.mean_direct_lx) {
    d.reason = IndirectReason::below_threshold;
    return d;
  }
  d.run = true;
  d.reason = IndirectReason::estimate;
  return d;
}

}  // namespace luxgrid::calc::indirect
