// Intensity lookups, the hot path of every emitter model: ns per lookup for the raw table
// (bilinear, bicubic) and the resampled light distribution texture (bilinear, bicubic), on a
// large full-sphere file and a small rotational one. Directions are random unit vectors drawn
// once, so the timing is the lookup alone.
//   build-photometry/bench/photometry_bench --benchmark_filter=Lookup
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <random>
#include <vector>

#include "photometry/distribution_texture.h"
#include "photometry/photometry.h"
#include "photometry/tabular_distribution.h"

namespace {

using namespace luxgrid;
using namespace luxgrid::photometry;

const char* const kFiles[] = {
    "tests/data/photometry/ldt/sample18_mc360_large.ldt",     // 360 x 181
    "tests/data/photometry/ies/rab_roadway_199x38_lm02.ies",  // irregular
    "tests/data/photometry/ies/bega_6339_lm95_mult089.ies"};  // rotational

std::vector<Vec3> directions() {
  std::mt19937 rng(42);
  std::normal_distribution<double> n;
  std::vector<Vec3> d(4096);
  for (auto& v : d) v = glm::normalize(Vec3(n(rng), n(rng), n(rng)));
  return d;
}

// The data live in the source tree: this file's folder's parent (CMake compiles with absolute
// paths), or $LUXGRID_SOURCE_DIR when set.
std::string source_path(int k) {
  const char* env = std::getenv("LUXGRID_SOURCE_DIR");
  const std::filesystem::path root =
      env ? std::filesystem::path(env)
          : std::filesystem::path(__FILE__).parent_path().parent_path();
  return (root / kFiles[k]).string();
}

void run(benchmark::State& state, const IntensityDistribution& d) {
  const auto dirs = directions();
  std::size_t k = 0;
  double sum = 0.0;
  for (auto _ : state) {
    sum += d.intensity(dirs[k]);
    k = (k + 1) & 4095;
  }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations());
}

void LookupTable(benchmark::State& state) {
  const Photometry p = load_photometry_file(source_path(static_cast<int>(state.range(0))));
  const auto t = p.table->with_interpolation(state.range(1) ? Interpolation::bicubic
                                                            : Interpolation::bilinear);
  state.SetLabel(std::string(state.range(1) ? "bicubic" : "bilinear") + " raw " +
                 kFiles[state.range(0)]);
  run(state, *t);
}

void LookupTexture(benchmark::State& state) {
  const Photometry p = load_photometry_file(source_path(static_cast<int>(state.range(0))));
  const Interpolation mode = state.range(1) ? Interpolation::bicubic : Interpolation::bilinear;
  const DistributionTexture tex(*p.table, 1440, 720, mode);
  state.SetLabel(std::string(state.range(1) ? "bicubic" : "bilinear") + " texture 1440x720 " +
                 kFiles[state.range(0)]);
  run(state, tex);
}

void LoadFile(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(load_photometry_file(source_path(static_cast<int>(state.range(0)))));
  state.SetLabel(kFiles[state.range(0)]);
}

BENCHMARK(LookupTable)->ArgsProduct({{0, 1, 2}, {0, 1}});
BENCHMARK(LookupTexture)->ArgsProduct({{0, 1, 2}, {0, 1}});
BENCHMARK(LoadFile)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
