// calc/nearfield/far_run.h: a point's far-field pairs looked up together against
// far_field_illuminance pair by pair, bit for bit: tables with one C plane and many, bilinear and
// bicubic, in a rotated grid frame (type A/B: one by one), wrapped once and twice in
// calc::ScaledDistribution, a distribution without a run look-up of its own, a light-distribution
// texture; luminaires turned and not, points below, beside, behind and at a luminaire, the
// vertical below one (where the table's angles are not lanes).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "calc/nearfield/far_run.h"
#include "calc/nearfield/models.h"
#include "calc/scaled_distribution.h"
#include "photometry/builtin.h"
#include "photometry/distribution_texture.h"
#include "photometry/photometry.h"
#include "photometry/tabular_distribution.h"

namespace luxgrid::calc {
namespace {

// A table of `planes` C planes at 5-degree gamma steps, values that vary in both angles.
std::shared_ptr<photometry::TabularDistribution> table(int planes, photometry::Interpolation mode,
                                                       const glm::dmat3& frame = glm::dmat3(1.0)) {
  photometry::SphericalGrid g;
  for (int i = 0; i < planes; ++i) g.c_rad.push_back(2.0 * kPi * i / planes);
  for (int j = 0; j <= 36; ++j) g.gamma_rad.push_back(kPi * j / 36);
  for (int i = 0; i < planes; ++i)
    for (int j = 0; j <= 36; ++j)
      g.cd.push_back(500.0 + 300.0 * std::cos(0.1 * j) * (1.0 + 0.3 * std::sin(1.0 * i + 0.2 * j)));
  return std::make_shared<photometry::TabularDistribution>(std::move(g), mode, frame);
}

TEST(FarPairs, SameBitsAsFarFieldIlluminancePairByPair) {
  const photometry::Photometry mirel = photometry::load_photometry_file(
      std::string(LUXGRID_SOURCE_DIR) + "/tests/data/photometry/ldt/zumtobel_mirel_isym4.ldt");
  // A distribution without a run look-up of its own.
  const auto lambertian = std::make_shared<photometry::LambertianDistribution>(300.0);
  const photometry::DistributionTexture texture(*lambertian, 96, 48);
  const glm::dmat3 type_b_frame(0.0, 0.0, 1.0, 0.0, 1.0, 0.0, -1.0, 0.0, 0.0);
  std::vector<photometry::DistributionPtr> dists = {
      mirel.distribution,
      table(1, photometry::Interpolation::bilinear),
      table(24, photometry::Interpolation::bicubic),
      table(24, photometry::Interpolation::bilinear, type_b_frame),
      std::make_shared<ScaledDistribution>(mirel.distribution, 0.83),
      std::make_shared<ScaledDistribution>(
          std::make_shared<ScaledDistribution>(table(24, photometry::Interpolation::bilinear), 1.7),
          0.3),
      lambertian};
  std::mt19937_64 rng(39);
  std::uniform_real_distribution<double> u(-5.0, 5.0), angle(0.0, 6.283185307179586);
  std::vector<nearfield::Emitter> emitters;
  for (size_t k = 0; k < 3 * dists.size() + 1; ++k) {
    nearfield::Emitter e;
    e.centroid = Vec3(u(rng), u(rng), 3.0 + 0.1 * u(rng));
    const double a = k % 2 == 0 ? 0.0 : angle(rng);
    const glm::dmat3 rotation(std::cos(a), std::sin(a), 0.0, -std::sin(a), std::cos(a), 0.0, 0.0,
                              0.0, 1.0);
    e.rotation = rotation, e.world_to_local = glm::transpose(rotation);
    e.distribution = dists[k % dists.size()];
    emitters.push_back(e);
  }
  // The texture as a far-field lookup of its own (what calc/intensity_lookup attaches).
  emitters[1].far_distribution =
      std::shared_ptr<const photometry::IntensityDistribution>(lambertian, &texture);
  std::vector<const nearfield::Emitter*> run;
  for (const auto& e : emitters) run.push_back(&e);
  // A run of one lookup across two passes of 64, and one alternating between lookups.
  for (int k = 0; k < 70; ++k) run.push_back(&emitters[4]);
  for (int k = 0; k < 30; ++k) run.push_back(&emitters[k % 3]);
  std::vector<Vec3> points;
  for (int i = 0; i < 200; ++i) points.push_back(Vec3(u(rng), u(rng), 0.8 * (i % 5)));
  points.push_back(emitters[0].centroid);                        // at a luminaire
  points.push_back(emitters[2].centroid - Vec3(0, 0, 2.0));      // the vertical below one
  points.push_back(emitters[3].centroid + Vec3(1.0, 0.0, 0.0));  // in its plane
  int differ = 0, lit = 0;
  std::vector<double> out(run.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3 normal = i % 7 == 3 ? Vec3(0, 0, -1)  // facing away: every pair behind it
                                   : glm::normalize(Vec3(0.3 * u(rng), 0.3 * u(rng), 1.0));
    nearfield::far_field_pairs(run.data(), run.size(), points[i], normal, out.data());
    for (size_t k = 0; k < run.size(); ++k) {
      const double one = nearfield::far_field_illuminance(*run[k], points[i], normal);
      differ += std::memcmp(&one, &out[k], sizeof one) != 0;
      lit += one > 0.0;
    }
  }
  EXPECT_EQ(differ, 0);
  EXPECT_GT(lit, 1000);
}

}  // namespace
}  // namespace luxgrid::calc
