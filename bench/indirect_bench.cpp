// How calc/indirect's time and memory grow with the patch count (docs/indirect.md, performance): a
// 12 x 8 x 3 m room (floor 0.2, walls 0.5, ceiling 0.7) with 6 Lambertian downlights and a
// 0.25 m workplane grid (1 353 points), solved at patch sizes from 1 m to 0.25 m, converged
// (`auto`) and one bounce. Counters: patches, VPLs, form-factor matrix size (the dominant memory:
// n^2 floats; the mesh and vectors are O(n)), bounces run. Beside it the kernel that dominates
// the final gather: Lambert's exact point-to-polygon factor (form_factor.h) of a 0.25 m patch
// from points within 1 m of it (as the gather takes it: patches within half the far ratio of a
// receiver), wholly in front of the receiver or cut by its horizon.
// Run: build/bench/indirect_bench --benchmark_min_time=0.01
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "calc/indirect/form_factor.h"
#include "calc/indirect/indirect.h"
#include "photometry/builtin.h"

namespace {

using namespace luxgrid;
using namespace luxgrid::calc;

Scene bench_room() {
  Scene s;
  s.name = "bench";
  Room r;
  r.name = "room";
  r.outline = {{0, 0}, {12, 0}, {12, 8}, {0, 8}};
  r.height = 3.0;
  r.reflectance = {0.2, 0.5, 0.7};
  s.rooms = {r};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) {
      Luminaire l;
      l.label = "downlight";
      l.pose.position = Vec3(2.0 + 4.0 * i, 2.0 + 4.0 * j, 2.99);
      l.distribution = std::make_shared<photometry::LambertianDistribution>(1000.0);
      s.luminaires.push_back(l);
    }
  s.surfaces = {geometry::make_plane_grid("workplane", {0.5, 0.5, 0.75}, {1, 0, 0}, {0, 1, 0}, 11.0,
                                          7.0, 0.25)};
  return s;
}

void BM_Indirect(benchmark::State& state) {
  const Scene scene = bench_room();
  indirect::IndirectOptions o;
  o.patch_size_m = static_cast<double>(state.range(0)) / 100.0;
  o.bounces = static_cast<int>(state.range(1));
  o.max_patches_per_room = 20000;
  indirect::IndirectResult r;
  for (auto _ : state) {
    r = indirect::compute_indirect(scene, scene.surfaces, o);
    benchmark::DoNotOptimize(r.E_indirect_per_surface.data());
  }
  const double n = static_cast<double>(r.patches);
  state.counters["patches"] = n;
  state.counters["vpls"] = static_cast<double>(r.vpls);
  state.counters["bounces"] = r.bounces_run;
  // The one-bounce path builds no form factors.
  state.counters["FF_MB"] = o.bounces == 1 ? 0.0 : n * n * sizeof(float) / 1e6;
}

// Patch size in cm; bounces (0 = auto, 1 = one bounce).
BENCHMARK(BM_Indirect)
    ->ArgsProduct({{100, 70, 50, 35, 25}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Lambert's factor of a 0.25 m square patch (z = 0) from 4096 points 1 mm to 0.9 m above it and
// up to 0.9 m beside it; receiver normals tilted at random towards the patch (argument 0: every
// patch wholly above the receiver's horizon) or within 60 degrees of the horizontal (1: about
// two in five cut by it).
void BM_PointPolygonFormFactor(benchmark::State& state) {
  const std::vector<Vec3> patch = {{0, 0, 0}, {0.25, 0, 0}, {0.25, 0.25, 0}, {0, 0.25, 0}};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double down = state.range(0) == 0 ? 5.0 : 0.0;
  std::vector<Vec3> x, n;
  for (int i = 0; i < 4096; ++i) {
    x.emplace_back(0.125 + 0.9 * u(rng), 0.125 + 0.9 * u(rng), 0.001 + 0.9 * std::abs(u(rng)));
    n.push_back(glm::normalize(Vec3(u(rng), u(rng), -(down + std::abs(u(rng))))));
  }
  for (auto _ : state)
    for (size_t i = 0; i < x.size(); ++i)
      benchmark::DoNotOptimize(indirect::point_polygon_form_factor(x[i], n[i], patch));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(x.size()));
}
BENCHMARK(BM_PointPolygonFormFactor)->Arg(0)->Arg(1);

}  // namespace
