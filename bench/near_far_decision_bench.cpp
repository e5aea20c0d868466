// ns per luminaire-point pair of the near/far decision itself (docs/nearfield.md): the error-bound
// map's weights (calc/nearfield/far_field_bound.h: direction into the luminaire frame, C and
// gamma, a bilinear read of d_far and d_fixed) against the five-times rule (one distance), the
// one-off cost of building the map for the office's Mirel, and what one distant near-field pair
// costs by the table rung and by the fixed rule (calc/nearfield/fixed_rule.h).
// Run: build/bench/near_far_decision_bench --benchmark_min_time=0.2
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "calc/nearfield/far_field_bound.h"
#include "calc/nearfield/fixed_rule.h"
#include "calc/nearfield/illuminance.h"
#include "photometry/photometry.h"

namespace {

using namespace luxgrid;
using namespace luxgrid::nearfield;

Emitter mirel() {
  const auto ph =
      photometry::load_photometry_file(std::string(LUXGRID_BENCH_SOURCE_DIR) +
                                       "/tests/data/photometry/ldt/zumtobel_mirel_isym4.ldt");
  return make_emitter(ph.opening, Vec3(0, 0, 3), glm::dmat3(1.0), ph.distribution);
}

// Receivers of an open-plan floor: 30 x 18 m at 0.75 m, luminaire at (0, 0, 3).
std::vector<Vec3> floor_points() {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> x(-15.0, 15.0), y(-9.0, 9.0);
  std::vector<Vec3> out;
  for (int i = 0; i < 4096; ++i) out.push_back(Vec3(x(rng), y(rng), 0.75));
  return out;
}

void weight(benchmark::State& state, bool with_bound) {
  Emitter e = mirel();
  if (with_bound) e.far_bound = build_far_field_bound(e, Model::standard(), kStandardPromise);
  const std::vector<Vec3> pts = floor_points();
  std::size_t i = 0;
  double sink = 0.0;
  for (auto _ : state) {
    const SwitchWeights w = switch_weights(e, pts[i]);
    sink += w.far + w.fixed;
    if (++i == pts.size()) i = 0;
  }
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(state.iterations());
}

void DecisionErrorBound(benchmark::State& s) { weight(s, true); }
void DecisionFiveTimesRule(benchmark::State& s) { weight(s, false); }
BENCHMARK(DecisionErrorBound);
BENCHMARK(DecisionFiveTimesRule);

void BuildMapMirel(benchmark::State& state) {
  const Emitter e = mirel();
  for (auto _ : state)
    benchmark::DoNotOptimize(build_far_field_bound(e, Model::standard(), kStandardPromise));
}
BENCHMARK(BuildMapMirel)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

// One pair 8 to 15 m from the Mirel (16 to 30 D) on the floor: the distances where the open plan's
// near-field pairs sit.
std::vector<Vec3> distant_points() {
  std::vector<Vec3> out;
  for (const Vec3& p : floor_points())
    if (glm::length(p - Vec3(0, 0, 3)) > 8.0) out.push_back(p);
  return out;
}

void pair(benchmark::State& state, bool fixed) {
  const Emitter e = mirel();
  const std::vector<Vec3> pts = distant_points();
  const Receiver up = Receiver::planar(Vec3(0, 0, 1));
  std::size_t i = 0;
  double sink = 0.0;
  for (auto _ : state) {
    sink += fixed ? fixed_rule_illuminance(e, pts[i], up)
                  : illuminance(e, pts[i], up, Model::standard());
    if (++i == pts.size()) i = 0;
  }
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(state.iterations());
}

void DistantPairTableRung(benchmark::State& s) { pair(s, false); }
void DistantPairFixedRule(benchmark::State& s) { pair(s, true); }
BENCHMARK(DistantPairTableRung);
BENCHMARK(DistantPairFixedRule);
