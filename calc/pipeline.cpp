#include "calc/pipeline.h"

#include <chrono>

#include "calc/indirect/indirect.h"

namespace luxgrid::calc {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Direct light on every surface; progress runs from 0 to 1 over all points.
void run_direct(const Scene& scene, Results& results, const Progress& progress) {
  size_t total_points = 0;
  for (const auto& s : scene.surfaces) total_points += s.points.size();
  const auto emitters = make_emitters(scene);
  DirectCounts counts;
  size_t points_before = 0;
  for (const auto& grid : scene.surfaces) {
    SurfaceResult r;
    r.grid = grid;
    Progress surface_progress;
    if (progress && total_points > 0) {
      const double share = static_cast<double>(grid.points.size()) / total_points;
      const double offset = static_cast<double>(points_before) / total_points;
      surface_progress = [=](double f) { progress(offset + share * f); };
    }
    r.E_direct = direct_illuminance(results.plan, emitters, grid, surface_progress, &counts);
    r.E_indirect.assign(r.E_direct.size(), 0.0);
    points_before += grid.points.size();
    results.surfaces.push_back(std::move(r));
  }
  results.plan.direct = describe_direct(results.plan, counts);
}

// Reflected light, when the plan's decision says the scene needs it.
void run_indirect(const Scene& scene, Results& results) {
  const indirect::IndirectDecision decision = indirect::decide_indirect(scene);
  results.plan.indirect = decision.reason;
  if (!decision.run) return;
  indirect::IndirectOptions options = indirect::indirect_options(scene.settings);
  options.luminous_flux_lm = decision.luminous_flux_lm;
  if (auto vis = results.plan.visibility_test) {
    options.occluded = [vis](const Vec3& a, const Vec3& b) { return !vis->visible(a, b); };
  }
  const indirect::IndirectResult r = indirect::compute_indirect(scene, scene.surfaces, options);
  for (size_t k = 0; k < results.surfaces.size(); ++k) {
    results.surfaces[k].E_indirect = r.E_indirect_per_surface[k];
  }
  results.plan.indirect = r.summary;
  for (const auto& n : r.notes) results.plan.notes.push_back(n);
}
}  // namespace

Results run_scene(const Scene& scene, const Progress& progress) {
  Results results;
  results.project = scene.name;
  results.plan = make_plan(scene);

  const auto t_direct = std::chrono::steady_clock::now();
  run_direct(scene, results, progress);
  results.timing_s.emplace_back("direct", seconds_since(t_direct));

  const auto t_indirect = std::chrono::steady_clock::now();
  run_indirect(scene, results);
  results.timing_s.emplace_back("indirect", seconds_since(t_indirect));

  const double mf = scene.settings.maintenance_factor;
  for (auto& r : results.surfaces) {
    r.E.resize(r.E_direct.size());
    for (size_t i = 0; i < r.E.size(); ++i) r.E[i] = (r.E_direct[i] + r.E_indirect[i]) * mf;
    r.stats = compute_statistics(r.E, r.grid.active);
  }
  return results;
}

}  // namespace luxgrid::calc
