// calc/direct's far-field run (far_field_run: a run of points against every luminaire, the
// textures looked up a run at once) against point_source_illuminance one pair at a time, bit for
// bit, in each version the multiversioning macro makes: luminaires with a texture and without,
// turned and not, points below, beside and at a luminaire, inactive points.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <random>
#include <vector>

#include "calc/direct.h"
#include "calc/nearfield/models.h"
#include "photometry/builtin.h"
#include "photometry/distribution_texture.h"

namespace luxgrid::calc {
namespace {

// I = 100 (1 + x^2 + 2 y^2) cd in the luminaire frame: not rotationally symmetric.
class Asymmetric final : public photometry::IntensityDistribution {
 public:
  double intensity(const Vec3& d) const override {
    return 100.0 * (1.0 + d.x * d.x + 2.0 * d.y * d.y);
  }
};

using FarFieldRun = void (*)(const std::vector<nearfield::Emitter>&, const std::vector<uint32_t>&,
                             const geometry::SurfaceGrid&, size_t, size_t, std::vector<double>&);
void expect_run_same_bits_as_pairs(FarFieldRun run) {
  std::mt19937_64 rng(35);
  std::uniform_real_distribution<double> u(-3.0, 3.0), angle(0.0, 6.283185307179586);
  const auto asymmetric = std::make_shared<Asymmetric>();
  const photometry::DistributionTexture texture(*asymmetric, 96, 48);
  std::vector<nearfield::Emitter> emitters(6);
  for (size_t k = 0; k < emitters.size(); ++k) {
    nearfield::Emitter& e = emitters[k];
    e.centroid = Vec3(u(rng), u(rng), 3.0 + 0.1 * u(rng));
    const double a = angle(rng);
    const glm::dmat3 rotation(std::cos(a), std::sin(a), 0.0, -std::sin(a), std::cos(a), 0.0, 0.0,
                              0.0, 1.0);
    e.rotation = rotation, e.world_to_local = glm::transpose(rotation);
    e.distribution = asymmetric;
    if (k % 2 == 0) e.far_texture = &texture, e.far_texture_factor = 0.5 + 0.25 * k;
  }
  std::vector<uint32_t> luminaires = {0, 1, 2, 3, 4, 5, 2};  // one twice: the order counts
  geometry::SurfaceGrid grid;
  for (size_t i = 0; i < kFarFieldRun; ++i) {
    Vec3 p(u(rng), u(rng), 0.8 * (i % 3));
    if (i == 7) p = emitters[1].centroid;                         // at a luminaire
    if (i == 9) p = emitters[0].centroid;                         // at a textured one
    if (i == 11) p = emitters[2].centroid + Vec3(1.0, 0.0, 0.0);  // in its plane
    grid.points.push_back(p);
    grid.normals.push_back(glm::normalize(Vec3(0.2 * u(rng), 0.2 * u(rng), 1.0)));
    grid.active.push_back(i % 13 != 5);
  }
  std::vector<double> E(grid.points.size(), -1.0);
  run(emitters, luminaires, grid, 0, grid.points.size(), E);
  int differ = 0, lit = 0;
  for (size_t i = 0; i < grid.points.size(); ++i) {
    if (!grid.active[i]) {
      EXPECT_EQ(E[i], -1.0);  // left alone
      continue;
    }
    double sum = 0.0;
    for (const uint32_t k : luminaires) {
      const nearfield::Emitter& e = emitters[k];
      const nearfield::Receiver planar = nearfield::Receiver::planar(grid.normals[i]);
      sum += e.far_texture
                 ? nearfield::point_source_illuminance_with(
                       [&](const Vec3& local, double) {
                         return e.far_texture_factor * e.far_texture->bilinear(local);
                       },
                       e.world_to_local, e.centroid, grid.points[i], planar)
                 : nearfield::point_source_illuminance(*e.distribution, e.world_to_local,
                                                       e.centroid, grid.points[i], planar);
    }
    differ += std::memcmp(&sum, &E[i], sizeof sum) != 0;
    lit += sum > 0.0;
  }
  EXPECT_EQ(differ, 0);
  EXPECT_GT(lit, 50);
}

TEST(FarFieldRun, SameBitsAsPairByPairAvx2) {
  if (!simd::cpu_has_avx2()) GTEST_SKIP() << "this processor has no AVX2";
  expect_run_same_bits_as_pairs(far_field_run_avx2);
}
TEST(FarFieldRun, SameBitsAsPairByPairDefault) {
  expect_run_same_bits_as_pairs(far_field_run_default);
}

}  // namespace
}  // namespace luxgrid::calc
