#include "calc/daylight_run.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

#include <tbb/parallel_for.h>

#include "calc/daylight_light.h"
#include "calc/daylight_sun.h"
#include "calc/indirect/indirect.h"
#include "calc/pipeline.h"
#include "calc/plan_estimates.h"
#include "calc/statistics.h"

namespace luxgrid::calc {

double daylight_tolerance(Quality q) {
  switch (q) {
    case Quality::draft: return 0.05;
    case Quality::standard:
    case Quality::high: return promised_error(q);
    case Quality::reference: return 1e-4;
  }
  return 0.01;
}

namespace {

// Direct sunlight (calc/daylight_sun.h), no part of DF: at every point the sun through the
// openings, and its reflected light from a run of the reflected light of its own with the sun's
// flux on the patches as the first bounce (the sky's run stays as it was, so DF and IRC are the
// same with the sun on or off); both added to E_direct, E_indirect and E, and kept apart as
// E_sun_direct and E_sun_reflected.
void add_direct_sun(const Scene& geometry_only, const geometry::Visibility* visibility,
                    const std::shared_ptr<const geometry::Visibility>& visibility_test,
                    Results& results, DaylightPlan& dp) {
  const DaylightSun sun(geometry_only, visibility);
  dp.direct_sun = true;
  dp.direct_normal_lx = sun.direct_normal_lx();
  dp.sun_shadow_samples = visibility ? DaylightSun::kShadowSamplesPerSide : 0;
  for (std::size_t k = 0; k < sun.openings(); ++k)
    dp.sun_flux_entering_lm += sun.entering_flux_lm(k);
  for (SurfaceResult& r : results.surfaces) {
    const geometry::SurfaceGrid& g = r.grid;
    r.E_sun_direct.assign(g.points.size(), 0.0);
    r.E_sun_reflected.assign(g.points.size(), 0.0);
    tbb::parallel_for(std::size_t{0}, g.points.size(), [&](std::size_t i) {
      if (!g.active.empty() && !g.active[i]) return;
      r.E_sun_direct[i] = sun.at(g.points[i], g.normals[i]);
    });
  }
  dp.sun_reflected = dp.internally_reflected;
  if (dp.sun_reflected) {
    Results sun_results;
    for (const SurfaceResult& r : results.surfaces) {
      SurfaceResult s;
      s.grid = r.grid;
      s.E_direct = r.E_sun_direct;  // the estimate's floor (plan_estimates.h)
      sun_results.surfaces.push_back(std::move(s));
    }
    indirect::IndirectOptions options = indirect::indirect_options(geometry_only.settings);
    options.visibility = visibility_test;
    options.incident_flux_lm = [&sun](const indirect::PatchMesh& mesh) {
      return sun.patch_flux_lm(mesh);
    };
    const IndirectEstimateInputs est = run_reflected_light(geometry_only, options, sun_results);
    dp.sun_flux_on_surfaces_lm = sun_results.plan.indirect_run->received_flux_lm;
    dp.sun_flux_escaping_lm = est.escaped_flux_lm;
    dp.sun_patches = sun_results.plan.indirect_run->patches;
    dp.sun_patch_size_m = sun_results.plan.indirect_run->patch_size_m;
    for (std::size_t k = 0; k < results.surfaces.size(); ++k)
      results.surfaces[k].E_sun_reflected = sun_results.surfaces[k].E_indirect;
  }
  for (SurfaceResult& r : results.surfaces) {
    for (std::size_t i = 0; i < r.E.size(); ++i) {
      r.E_direct[i] += r.E_sun_direct[i];
      r.E_indirect[i] += r.E_sun_reflected[i];
      r.E[i] = r.E_direct[i] + r.E_indirect[i];
    }
    r.stats = compute_statistics(r.E, r.grid.active);
  }
}

}  // namespace

Results run_daylight_scene(const Scene& scene, const Progress& progress) {
  (void)progress;
  const auto t0 = std::chrono::steady_clock::now();
  const DaylightInputs& inputs = *scene.daylight;
  Results results;
  results.project = scene.name;
  results.scene = LightingScene::daylight;
  results.quality = scene.settings.quality;
  results.maintenance_factor = 1.0;  // openings carry their own maintenance factors
  for (const auto& g : scene.surfaces) {
    if (g.kind == geometry::SurfaceGrid::Kind::observers)
      throw InputError(
          SourceLocation(),
          "surface '" + g.name + "': the daylight scene calculates no glare (observers surfaces)");
    if (g.quantity == geometry::Quantity::cylindrical ||
        g.quantity == geometry::Quantity::semi_cylindrical)
      throw InputError(SourceLocation(), "surface '" + g.name +
                                             "': the daylight scene calculates planar, "
                                             "horizontal and vertical illuminance only (not built "
                                             "for " +
                                             geometry::to_string(g.quantity) + ")");
  }

  // The scene's occlusion test (obstacles, non-convex rooms), without the luminaires: the
  // daylight scene lights nothing electric.
  Scene geometry_only = scene;
  geometry_only.luminaires.clear();
  Plan plan;
  plan.quality = scene.settings.quality;
  plan.visibility_test = make_visibility(geometry_only, plan.visibility);
  const geometry::Visibility* visibility = plan.visibility_test.get();

  DaylightPlan dp;
  dp.sky = inputs.sky.name();
  dp.diffuse_horizontal_lx = inputs.diffuse_horizontal_lx;
  dp.ground_reflectance = inputs.ground_reflectance;
  if (inputs.sun) {
    dp.has_sun = true;
    dp.sun_altitude_deg = inputs.sun->altitude_deg, dp.sun_azimuth_deg = inputs.sun->azimuth_deg;
  }
  dp.sun_from_site = inputs.sun_from_site;
  dp.relative_tolerance = daylight_tolerance(scene.settings.quality);
  const DaylightLight light(scene, visibility, dp.relative_tolerance);
  const daylight::QuadratureResult& norm = light.sky_integral();
  dp.sky_integral_sr = norm.value, dp.sky_integral_error_sr = norm.error_estimate;
  dp.openings = scene.openings.size();
  for (const auto& o : scene.openings) dp.glazed_openings += o.glazing_transmittance.has_value();
  dp.exterior_obstructions = inputs.obstructions.size();
  dp.ground_exact = light.ground_exact();
  dp.sky_exact = light.sky_exact();
  dp.luminaires_left_out = scene.luminaires.size();
  for (const Room& room : scene.rooms) {
    const Reflectances& rho = room.reflectance;
    dp.reflecting_surfaces =
        dp.reflecting_surfaces || rho.floor > 0.0 || rho.walls > 0.0 || rho.ceiling > 0.0;
    for (const auto& o : room.obstacles)
      dp.reflecting_surfaces = dp.reflecting_surfaces || o.reflectance > 0.0;
  }
  dp.indirect_off = scene.settings.indirect == IndirectMode::off;

  std::atomic<std::size_t> evaluations{0}, outside{0};
  // What the plan's estimate counts as the direct part's error (plan_estimates.h): the sky and
  // ground integrations' own estimates, lx.
  DirectEstimateInputs direct_estimate;
  for (const auto& g : scene.surfaces) {
    SurfaceResult r;
    r.grid = g;
    const std::size_t n = g.points.size();
    r.SC.assign(n, 0.0), r.ERC.assign(n, 0.0), r.IRC.assign(n, 0.0), r.DF.assign(n, 0.0);
    std::vector<double> sky_error(n, 0.0), ground_error(n, 0.0);
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
      if (!g.active.empty() && !g.active[i]) return;
      bool in_a_room = false;
      for (const Room& room : scene.rooms) in_a_room = in_a_room || inside_room(room, g.points[i]);
      if (!in_a_room) {
        outside.fetch_add(1, std::memory_order_relaxed);
        return;
      }
      const OpeningLightParts p = light.at(g.points[i], g.normals[i]);
      r.SC[i] = light.sky_percent(p.sky);
      r.ERC[i] = light.external_percent(p);
      sky_error[i] = light.sky_percent(p.sky_error);
      ground_error[i] = light.external_error_percent(p);
      evaluations.fetch_add(p.evaluations, std::memory_order_relaxed);
    });
    std::vector<double> error_lx(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      dp.sky_error_percent = std::max(dp.sky_error_percent, sky_error[i]);
      dp.ground_error_percent = std::max(dp.ground_error_percent, ground_error[i]);
      error_lx[i] = (sky_error[i] + ground_error[i]) * inputs.diffuse_horizontal_lx / 100.0;
    }
    direct_estimate.error_lx.push_back(std::move(error_lx));
    // E under the given sky: DF x E_h / 100, the light arriving straight through the openings
    // as E_direct, the internally reflected component as E_indirect (filled below).
    r.E_direct.resize(n), r.E_indirect.assign(n, 0.0), r.E.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      r.E_direct[i] = (r.SC[i] + r.ERC[i]) * inputs.diffuse_horizontal_lx / 100.0;
    results.surfaces.push_back(std::move(r));
  }

  const auto t1 = std::chrono::steady_clock::now();
  results.timing_s.emplace_back("daylight", std::chrono::duration<double>(t1 - t0).count());

  // The internally reflected component: the reflected light's converged interreflection
  // (calc/indirect) with the light entering through the openings as its first bounce, the
  // openings holes in the patch mesh (patches.h). Its estimate is the electric scenes' (the
  // mesh at twice the patch size on probe points, the bounces' residual).
  results.plan = std::move(plan);
  IndirectEstimateInputs indirect_estimate;
  dp.internally_reflected = dp.reflecting_surfaces && !dp.indirect_off && !scene.openings.empty();
  if (dp.internally_reflected) {
    indirect::IndirectOptions options = indirect::indirect_options(scene.settings);
    options.visibility = results.plan.visibility_test;
    options.incident_flux_lm = [&light](const indirect::PatchMesh& mesh) {
      return light.patch_flux_lm(mesh);
    };
    options.cell_incident_flux_lm = [&light](const indirect::PatchMesh& mesh,
                                             const indirect::CellMesh& cells) {
      return light.cell_flux_lm(mesh, cells);
    };
    indirect_estimate = run_reflected_light(geometry_only, options, results);
    for (std::size_t k = 0; k < light.openings(); ++k)
      dp.flux_entering_lm += light.entering_flux_lm(k);
    dp.flux_on_surfaces_lm = results.plan.indirect_run->received_flux_lm;
    dp.flux_escaping_lm = indirect_estimate.escaped_flux_lm;
  }
  for (SurfaceResult& r : results.surfaces) {
    for (std::size_t i = 0; i < r.E.size(); ++i) {
      r.IRC[i] = r.E_indirect[i] * 100.0 / inputs.diffuse_horizontal_lx;
      r.DF[i] = r.SC[i] + r.ERC[i] + r.IRC[i];
      r.E[i] = r.E_direct[i] + r.E_indirect[i];
    }
    r.stats = compute_statistics(r.E, r.grid.active);
  }
  dp.evaluations = evaluations.load();
  dp.points_outside_rooms = outside.load();
  results.plan.daylight = dp;
  // The estimates are of the sky's light (what DF holds); the sun's is added after them.
  estimate_errors(results, direct_estimate, indirect_estimate);
  if (inputs.direct_normal_lx)
    add_direct_sun(geometry_only, visibility, results.plan.visibility_test, results,
                   *results.plan.daylight);
  if (dp.internally_reflected)
    results.timing_s.emplace_back(
        "indirect", std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count());
  return results;
}

}  // namespace luxgrid::calc
