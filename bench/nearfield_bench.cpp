// ns per evaluation of each near-field model and rung (issue 5, item 7), averaged over the
// paper's protocol points (Luksch et al. 2020 Sec. 6: 1 x 1 emitter at heights 0.1 / 1 / 2.5,
// five orientations, a +-2.5 region on a 21 x 21 grid), for an analytic batwing profile and a
// tabulated (bilinear C-gamma) profile whose lookup costs what a photometric file's does.
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

namespace {

using namespace luxgrid;
using namespace luxgrid::nearfield;

// A 5-degree C x 2.5-degree gamma table, bilinear: the cost of a real file lookup (angles by
// atan2, two binary-search-free index computations, four table reads).
class TableDistribution final : public photometry::IntensityDistribution {
 public:
  TableDistribution() : table_(kC * kG) {
    for (int c = 0; c < kC; ++c)
      for (int g = 0; g < kG; ++g) {
        const double gamma = g * kDg, cc = c * kDc;
        table_[c * kG + g] = gamma < kPi / 2 ? 1000.0 * std::cos(gamma) * (1 + 2 * std::pow(std::sin(gamma), 2)) *
                                                   (1.0 + 0.2 * std::cos(2 * cc))
                                             : 0.0;
      }
  }
  double intensity(const Vec3& d) const override {
    const photometry::PhotometricAngles a = photometry::angles_of(d);
    const double fc = a.c / kDc, fg = a.gamma / kDg;
    const int c0 = std::min(int(fc), kC - 1), g0 = std::min(int(fg), kG - 2);
    const int c1 = (c0 + 1) % kC;
    const double tc = fc - c0, tg = fg - g0;
    const double v0 = table_[c0 * kG + g0] * (1 - tg) + table_[c0 * kG + g0 + 1] * tg;
    const double v1 = table_[c1 * kG + g0] * (1 - tg) + table_[c1 * kG + g0 + 1] * tg;
    return v0 * (1 - tc) + v1 * tc;
  }

 private:
  static constexpr int kC = 72, kG = 73;
  static constexpr double kDc = 2 * kPi / kC, kDg = kPi / (kG - 1);
  std::vector<double> table_;
};

struct Point {
  const Emitter* e;
  Vec3 p;
};

const std::vector<Emitter>& emitters(bool table) {
  static std::vector<Emitter> analytic, tabulated;
  std::vector<Emitter>& out = table ? tabulated : analytic;
  if (out.empty()) {
    photometry::DistributionPtr d = table ? photometry::DistributionPtr(std::make_shared<TableDistribution>())
                                          : std::make_shared<BatwingDistribution>(1000.0);
    photometry::LuminousOpening o;
    o.shape = photometry::LuminousOpening::Shape::rectangle;
    o.length = o.width = 1.0;
    for (double h : {0.1, 1.0, 2.5})
      for (double theta : {kPi / 2, 5 * kPi / 8, 3 * kPi / 4, 7 * kPi / 8, kPi})
        out.push_back(make_emitter(o, Vec3(0, 0, h),
                                   glm::dmat3(glm::rotate(glm::dmat4(1.0), kPi - theta, Vec3(0, 1, 0))), d));
  }
  return out;
}

std::vector<Point> protocol_points(bool table) {
  std::vector<Point> pts;
  for (const Emitter& e : emitters(table))
    for (int i = 0; i < 21; ++i)
      for (int j = 0; j < 21; ++j) pts.push_back({&e, Vec3(-2.5 + 0.25 * i + 0.01, -2.5 + 0.25 * j + 0.01, 0.0)});
  return pts;
}

void run(benchmark::State& state, const Model& model, bool table) {
  const std::vector<Point> pts = protocol_points(table);
  const Vec3 up(0, 0, 1);
  std::size_t i = 0;
  double sink = 0.0;
  for (auto _ : state) {
    const Point& p = pts[i];
    sink += illuminance(*p.e, p.p, up, model);
    if (++i == pts.size()) i = 0;
  }
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(state.iterations());
}

#define LUXGRID_MODEL_BENCH(name, model)                                            \
  void name##_analytic(benchmark::State& s) { run(s, model, false); }              \
  void name##_table(benchmark::State& s) { run(s, model, true); }                  \
  BENCHMARK(name##_analytic);                                                       \
  BENCHMARK(name##_table);

LUXGRID_MODEL_BENCH(FarField, Model::far_field())
LUXGRID_MODEL_BENCH(PaperCubature, Model::paper_cubature())
LUXGRID_MODEL_BENCH(StructuredSampling, Model::structured_sampling())
LUXGRID_MODEL_BENCH(Mrp, Model::most_representative_point())
LUXGRID_MODEL_BENCH(PaperK1, Model::subdivided(1))
LUXGRID_MODEL_BENCH(PaperK2, Model::subdivided(2))
LUXGRID_MODEL_BENCH(PaperK3, Model::subdivided(3))
LUXGRID_MODEL_BENCH(LambertProductK1, Model::lambert_subdivided(1))
LUXGRID_MODEL_BENCH(Standard, Model::standard())
LUXGRID_MODEL_BENCH(Adaptive1e2, Model::adaptive(1e-2))
LUXGRID_MODEL_BENCH(MonteCarlo64, Model::monte_carlo(64))
LUXGRID_MODEL_BENCH(Reference1e4, Model::reference(1e-4))

}  // namespace
