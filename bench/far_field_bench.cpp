// The far-field kernel (nearfield::point_source_illuminance, the point model of every far pair)
// with the two intensity lookups calc/intensity_lookup.h chooses between: the exact table (two
// atan2 per lookup) and the light distribution texture (diamond angles: additions, one division,
// one square root). ns per luminaire-point pair, on one core:
//   FarFieldPair:  the kernel alone, 100 luminaires x 10^4 points of the case below;
//   DirectPhase:   calc::direct_illuminance as the CLI's direct phase runs it at draft (far field
//                  everywhere), 1000 luminaires (40 x 25 panels, 2.5 x 2 m, 6 m high) x 10^4
//                  points (a 100 x 25 m plane at 0.75 m), the open plan's photometric file: the
//                  far1000 project of bench/make_projects.py. items_per_second = pairs/s/core.
//   build/bench/far_field_bench --benchmark_min_time=0.5
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <vector>

#include "calc/direct.h"
#include "calc/intensity_lookup.h"
#include "calc/nearfield/models.h"
#include "photometry/photometry.h"

namespace {

using namespace luxgrid;

std::string source_path(const char* rel) {
  return std::string(LUXGRID_BENCH_SOURCE_DIR) + "/" + rel;
}

struct Case {
  photometry::Photometry photometry;
  calc::IntensityLookup draft;  // the texture draft takes
  std::vector<nearfield::Emitter> table, texture;
  geometry::SurfaceGrid grid;
};

const Case& the_case() {
  static const Case c = [] {
    Case c;
    c.photometry =
        photometry::load_photometry_file(source_path("examples/openplan/photometry/"
                                                     "zumtobel_mirel_isym4.ldt"));
    c.draft = calc::choose_intensity_lookup(c.photometry.distribution, calc::Quality::draft);
    for (int j = 0; j < 25; ++j)
      for (int i = 0; i < 40; ++i) {
        c.table.push_back(nearfield::make_emitter(c.photometry.opening,
                                                  Vec3(1.25 + 2.5 * i, 1.0 + 2.0 * j, 6.0),
                                                  glm::dmat3(1.0), c.photometry.distribution));
        nearfield::Emitter e = c.table.back();
        e.far_distribution = c.draft.lookup;
        e.far_texture = c.draft.texture.get();
        c.texture.push_back(std::move(e));
      }
    c.grid.name = "grid";
    c.grid.nu = 200, c.grid.nv = 50;
    for (int j = 0; j < 50; ++j)
      for (int i = 0; i < 200; ++i) {
        c.grid.points.emplace_back(0.25 + 0.5 * i, 12.75 + 0.5 * j, 0.75);
        c.grid.normals.emplace_back(0.0, 0.0, 1.0);
      }
    c.grid.active.assign(c.grid.points.size(), true);
    return c;
  }();
  return c;
}

void FarFieldPair(benchmark::State& state) {
  const Case& c = the_case();
  const bool texture = state.range(0) != 0;
  const auto& emitters = texture ? c.texture : c.table;
  double sum = 0.0;
  for (auto _ : state) {
    for (size_t k = 0; k < 100; ++k) {
      const nearfield::Emitter& e = emitters[k * 10];
      for (size_t i = 0; i < c.grid.points.size(); ++i)
        sum += nearfield::point_source_illuminance(e.far_lookup(), e.world_to_local, e.centroid,
                                                   c.grid.points[i],
                                                   nearfield::Receiver::planar(c.grid.normals[i]));
    }
  }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations() * 100 * static_cast<int64_t>(c.grid.points.size()));
  state.SetLabel(texture ? "texture 1440x720 (virtual call)" : "table (atan2)");
}

void DirectPhase(benchmark::State& state) {
  const Case& c = the_case();
  const bool texture = state.range(0) != 0;
  tbb::global_control one_core(tbb::global_control::max_allowed_parallelism, 1);
  calc::Plan plan;
  plan.near_model = nearfield::Model::far_field();
  plan.near_switch = nearfield::NearFieldSwitch::never;
  double sum = 0.0;
  for (auto _ : state) {
    const std::vector<double> E =
        calc::direct_illuminance(plan, texture ? c.texture : c.table, c.grid);
    sum += E[E.size() / 2];
  }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(c.table.size()) *
                          static_cast<int64_t>(c.grid.points.size()));
  state.SetLabel(texture ? "texture 1440x720" : "table (atan2)");
}

BENCHMARK(FarFieldPair)->Arg(0)->Arg(1);
BENCHMARK(DirectPhase)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
