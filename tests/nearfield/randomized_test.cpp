// Issue 5, item 5: over 10^6 random configurations (fixed seed), no model returns NaN, Inf or a
// negative value. Configurations are drawn to hit the hard regions often: receivers near the
// emitter plane, on its edges, grazing normals, tiny and huge scales, every orientation.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "calc/nearfield/illuminance.h"
#include "calc/nearfield/models.h"
#include "calc/nearfield/receiver_fan.h"
#include "nearfield_test_support.h"

namespace luxgrid::nearfield {
namespace {

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Vec3 v(g(rng), g(rng), g(rng));
  const double l = glm::length(v);
  return l > 0.0 ? v / l : Vec3(0, 0, 1);
}

TEST(Randomized, MillionConfigurationsAreFiniteAndNonNegative) {
  constexpr int kConfigurations = 1'000'000;
  std::mt19937_64 rng(20240605);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const photometry::DistributionPtr dists[] = {testing::lambertian(), testing::isotropic(), testing::batwing(),
                                               testing::spot(), std::make_shared<ZeroPatchDistribution>(800.0)};
  int bad = 0;
  for (int k = 0; k < kConfigurations; ++k) {
    // A new emitter every 64 configurations.
    static thread_local Emitter e;
    if (k % 64 == 0) {
      photometry::LuminousOpening o;
      o.shape = u(rng) < 0.2 ? photometry::LuminousOpening::Shape::disk : photometry::LuminousOpening::Shape::rectangle;
      const double scale = std::pow(10.0, -3.0 + 6.0 * u(rng));
      o.length = scale * (0.05 + u(rng));
      o.width = scale * (0.05 + u(rng));
      const Vec3 axis = random_unit(rng);
      const glm::dmat3 r = glm::dmat3(glm::rotate(glm::dmat4(1.0), 2 * kPi * u(rng), axis));
      e = make_emitter(o, Vec3(u(rng), u(rng), u(rng)) * scale, r, dists[k / 64 % 5], 3 + int(u(rng) * 30));
    }
    const double size = e.largest_dimension_m;
    Vec3 p;
    const double mode = u(rng);
    if (mode < 0.3) {  // anywhere within 3 sizes
      p = e.centroid + (Vec3(u(rng), u(rng), u(rng)) - 0.5) * 6.0 * size;
    } else if (mode < 0.6) {  // near the emitter plane: 1e-12 .. 1e-1 of the size
      const Vec3 in = e.vertices[0] + (e.vertices[1] - e.vertices[0]) * (u(rng) * 1.4 - 0.2) +
                      (e.vertices[2 % e.vertices.size()] - e.vertices[1]) * (u(rng) * 1.4 - 0.2);
      const double off = std::pow(10.0, -12.0 + 11.0 * u(rng)) * size * (u(rng) < 0.5 ? -1 : 1);
      p = in + off * e.normal * (u(rng) < 0.1 ? 0.0 : 1.0);
    } else if (mode < 0.8) {  // on a vertex or an edge
      const std::size_t i = std::size_t(u(rng) * e.vertices.size()) % e.vertices.size();
      const std::size_t j = (i + 1) % e.vertices.size();
      p = e.vertices[i] + (u(rng) < 0.5 ? 0.0 : u(rng)) * (e.vertices[j] - e.vertices[i]) +
          e.normal * (u(rng) < 0.5 ? 0.0 : (u(rng) - 0.3) * 1e-3 * size);
    } else {  // far
      p = e.centroid + random_unit(rng) * size * std::pow(10.0, 4.0 * u(rng));
    }
    Vec3 n = random_unit(rng);
    if (u(rng) < 0.2) {  // grazing: normal almost in the emitter plane
      n = glm::normalize(glm::cross(e.normal, random_unit(rng)) + e.normal * (u(rng) - 0.5) * 1e-9);
    }
    // Cheap deterministic models on every configuration; the adaptive ones on a subset.
    double v[4] = {paper_cubature_illuminance(e, p, n), far_field_illuminance(e, p, n), 0.0, 0.0};
    if (k % 16 == 0) {
      v[2] = standard_illuminance(e, p, n);
      v[3] = subdivided_illuminance(e, p, n, 2, TriangleRule::two_kernel);
    }
    for (double x : v)
      if (!(std::isfinite(x) && x >= 0.0)) ++bad;
    // The raw published cubature (with the shift) must also be finite on its own.
    if (k % 8 == 0) {
      const double raw = paper_cubature_raw(e, p, n, horizon_shift_m(e));
      if (!(std::isfinite(raw) && raw >= 0.0)) ++bad;
    }
  }
  EXPECT_EQ(bad, 0);
}

}  // namespace
}  // namespace luxgrid::nearfield
