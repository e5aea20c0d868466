// ns per evaluation of each near-field model and rung (docs/accuracy.md), averaged over the
// paper's protocol points (Luksch et al. 2020 Sec. 6: 1 x 1 emitter at heights 0.1 / 1 / 2.5,
// five orientations, a +-2.5 region on a 21 x 21 grid), for an analytic batwing profile and a
// tabulated (bilinear C-gamma) profile whose lookup costs what a photometric file's does.
// The panel benchmarks: one 0.6 m panel (an IES table, 45-degree C planes, 5-degree gamma lines)
// 2.25 m above a 4 x 4 m workplane of 200 x 200 points facing up (bench/make_projects.py,
// panel40k): the standard rung against the far field per pair, the points in grid order.
// Run: build/bench/nearfield_bench --benchmark_min_time=0.2
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "calc/nearfield/analytic_profiles.h"
#include "calc/nearfield/illuminance.h"
#include "calc/nearfield/models.h"
#include "photometry/builtin.h"
#include "photometry/photometry.h"
#include "photometry/tabular_distribution.h"
#include "study/accuracy_study.h"

namespace {

using namespace luxgrid;
using namespace luxgrid::nearfield;

// A 5-degree C x 2.5-degree gamma table, bilinear, as the photometry reader builds it
// (photometry::TabularDistribution): a lookup costs what a file's does (two atan2, the cell by a
// multiplication, four table reads), and `standard` sees its table (the table rung).
photometry::DistributionPtr table_distribution() {
  constexpr int kC = 72, kG = 73;
  photometry::SphericalGrid grid;
  for (int c = 0; c < kC; ++c) grid.c_rad.push_back(c * 2 * kPi / kC);
  for (int g = 0; g < kG; ++g) grid.gamma_rad.push_back(g * kPi / (kG - 1));
  for (double cc : grid.c_rad)
    for (double gamma : grid.gamma_rad)
      grid.cd.push_back(gamma < kPi / 2
                            ? 1000.0 * std::cos(gamma) * (1 + 2 * std::pow(std::sin(gamma), 2)) *
                                  (1.0 + 0.2 * std::cos(2 * cc))
                            : 0.0);
  return std::make_shared<photometry::TabularDistribution>(std::move(grid));
}

struct Point {
  const Emitter* e;
  Vec3 p;
};

const std::vector<Emitter>& emitters(bool table) {
  static std::vector<Emitter> analytic, tabulated;
  std::vector<Emitter>& out = table ? tabulated : analytic;
  if (out.empty()) {
    photometry::DistributionPtr d =
        table ? table_distribution()
              : photometry::DistributionPtr(std::make_shared<BatwingDistribution>(1000.0));
    photometry::LuminousOpening o;
    o.shape = photometry::LuminousOpening::Shape::rectangle;
    o.length = o.width = 1.0;
    for (double h : {0.1, 1.0, 2.5})
      for (double theta : {kPi / 2, 5 * kPi / 8, 3 * kPi / 4, 7 * kPi / 8, kPi})
        out.push_back(
            make_emitter(o, Vec3(0, 0, h),
                         glm::dmat3(glm::rotate(glm::dmat4(1.0), kPi - theta, Vec3(0, 1, 0))), d));
  }
  return out;
}

std::vector<Point> protocol_points(bool table) {
  std::vector<Point> pts;
  for (const Emitter& e : emitters(table))
    for (int i = 0; i < 21; ++i)
      for (int j = 0; j < 21; ++j)
        pts.push_back({&e, Vec3(-2.5 + 0.25 * i + 0.01, -2.5 + 0.25 * j + 0.01, 0.0)});
  return pts;
}

void run(benchmark::State& state, const luxgrid::study::AccuracyModel& model, bool table) {
  const std::vector<Point> pts = protocol_points(table);
  const Vec3 up(0, 0, 1);
  std::size_t i = 0;
  double sink = 0.0;
  for (auto _ : state) {
    const Point& p = pts[i];
    sink += luxgrid::study::evaluate(model, *p.e, p.p, up, 1);
    if (++i == pts.size()) i = 0;
  }
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(state.iterations());
}

#define LUXGRID_MODEL_BENCH(name, model)                              \
  void name##_analytic(benchmark::State& s) { run(s, model, false); } \
  void name##_table(benchmark::State& s) { run(s, model, true); }     \
  BENCHMARK(name##_analytic);                                         \
  BENCHMARK(name##_table);

LUXGRID_MODEL_BENCH(FarField, luxgrid::study::AccuracyModel::rung(Model::far_field()))
LUXGRID_MODEL_BENCH(PaperCubature, luxgrid::study::AccuracyModel::rung(Model::paper_cubature()))
LUXGRID_MODEL_BENCH(StructuredSampling, luxgrid::study::AccuracyModel::structured_sampling())
LUXGRID_MODEL_BENCH(Mrp, luxgrid::study::AccuracyModel::most_representative_point())
LUXGRID_MODEL_BENCH(PaperK1, luxgrid::study::AccuracyModel::rung(Model::subdivided(1)))
LUXGRID_MODEL_BENCH(PaperK2, luxgrid::study::AccuracyModel::rung(Model::subdivided(2)))
LUXGRID_MODEL_BENCH(PaperK3, luxgrid::study::AccuracyModel::rung(Model::subdivided(3)))
LUXGRID_MODEL_BENCH(LambertProductK1,
                    luxgrid::study::AccuracyModel::rung(Model::lambert_subdivided(1)))
LUXGRID_MODEL_BENCH(Standard, luxgrid::study::AccuracyModel::rung(Model::standard()))
LUXGRID_MODEL_BENCH(Adaptive1e2, luxgrid::study::AccuracyModel::rung(Model::adaptive(1e-2)))
LUXGRID_MODEL_BENCH(MonteCarlo64, luxgrid::study::AccuracyModel::monte_carlo(64))
LUXGRID_MODEL_BENCH(Reference1e4, luxgrid::study::AccuracyModel::rung(Model::reference(1e-4)))

const Emitter& panel() {
  static const Emitter e = [] {
    photometry::Photometry ph =
        photometry::load_photometry_file(std::string(LUXGRID_BENCH_SOURCE_DIR) +
                                         "/tests/data/photometry/ies/indoor_full360_lm02.ies");
    ph.opening.shape = photometry::LuminousOpening::Shape::rectangle;
    ph.opening.length = ph.opening.width = 0.6;
    return make_emitter(ph.opening, Vec3(2, 2, 3), glm::dmat3(1.0), ph.distribution);
  }();
  return e;
}

void run_panel(benchmark::State& state, const Model& model) {
  std::vector<Vec3> pts;
  for (int j = 0; j < 200; ++j)
    for (int i = 0; i < 200; ++i) pts.push_back(Vec3(0.01 + 0.02 * i, 0.01 + 0.02 * j, 0.75));
  const Vec3 up(0, 0, 1);
  std::size_t i = 0;
  double sink = 0.0;
  for (auto _ : state) {
    sink += illuminance(panel(), pts[i], up, model);
    if (++i == pts.size()) i = 0;
  }
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(state.iterations());
}

void PanelWorkplane_FarField(benchmark::State& s) { run_panel(s, Model::far_field()); }
void PanelWorkplane_Standard(benchmark::State& s) { run_panel(s, Model::standard()); }
BENCHMARK(PanelWorkplane_FarField);
BENCHMARK(PanelWorkplane_Standard);

}  // namespace
