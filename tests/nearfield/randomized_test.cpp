// Over 10^5 random configurations (fixed seed), no model returns NaN, Inf or a negative value, and
// none exceeds an independent upper bound: every element dA of an opening of area A sends
// I(w) dA / A towards the receiver (radiance substitution [Luksch2020, Eq. 2]), so with
// cos(theta_r) <= 1 and every element at least d_min from the receiver,
//   E <= I_max / d_min^2,
// d_min the distance from the receiver to the opening's polygon. Configurations are drawn to hit
// the hard regions often: receivers near the emitter plane, on its edges, grazing normals, tiny
// and huge scales, every orientation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "calc/nearfield/illuminance.h"
#include "calc/nearfield/models.h"
#include "calc/nearfield/receiver_fan.h"
#include "nearfield_test_support.h"

namespace luxgrid::nearfield {
namespace {

Vec3 random_unit_or_z(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Vec3 v(g(rng), g(rng), g(rng));
  const double l = glm::length(v);
  return l > 0.0 ? v / l : Vec3(0, 0, 1);
}

// Distance (m) from p to the convex planar polygon v (its interior included).
double distance_to_polygon(const Emitter& e, const Vec3& p) {
  const auto& v = e.vertices;
  const double h = glm::dot(p - e.centroid, e.normal);
  const Vec3 q = p - h * e.normal;   // p projected into the plane
  bool left = false, right = false;  // q on the left / right of some edge (either orientation)
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < v.size(); ++i) {
    const Vec3 a = v[i], b = v[(i + 1) % v.size()];
    const double side = glm::dot(glm::cross(b - a, q - a), e.normal);
    left = left || side > 0.0;
    right = right || side < 0.0;
    const Vec3 ab = b - a;
    const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
    best = std::min(best, glm::length(p - (a + t * ab)));
  }
  return left && right ? best : std::abs(h);
}

// Largest intensity (cd) of a distribution, from a dense Fibonacci sphere of directions (the
// test's distributions are smooth analytic profiles, or constant patches of 800 cd).
double max_intensity(const photometry::IntensityDistribution& d) {
  constexpr int kDirections = 200'000;
  double best = 0.0;
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < kDirections; ++k) {
    const double z = 1.0 - 2.0 * (k + 0.5) / kDirections, r = std::sqrt(1.0 - z * z);
    best = std::max(best, d.intensity(Vec3(r * std::cos(golden * k), r * std::sin(golden * k), z)));
  }
  return best;
}

TEST(Randomized, ConfigurationsAreFiniteNonNegativeAndWithinTheIntensityBound) {
  constexpr int kConfigurations = 100'000;
  std::mt19937_64 rng(20240605);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const photometry::DistributionPtr dists[] = {testing::lambertian(), testing::isotropic(),
                                               testing::batwing(), testing::spot(),
                                               std::make_shared<ZeroPatchDistribution>(800.0)};
  double i_max[5];
  for (int d = 0; d < 5; ++d) i_max[d] = max_intensity(*dists[d]);
  // The bound is loose almost everywhere (cos(theta_r) and the spread over the opening); 2 %
  // covers the sampled I_max (the profiles change by far less between neighbouring directions
  // 0.5 deg apart) and the adaptive models' promised 1 %.
  constexpr double kBoundMargin = 1.02;
  int bad = 0, above = 0, bounded = 0;
  for (int k = 0; k < kConfigurations; ++k) {
    // A new emitter every 64 configurations.
    static thread_local Emitter e;
    if (k % 64 == 0) {
      photometry::LuminousOpening o;
      o.shape = u(rng) < 0.2 ? photometry::LuminousOpening::Shape::disk
                             : photometry::LuminousOpening::Shape::rectangle;
      const double scale = std::pow(10.0, -3.0 + 6.0 * u(rng));
      o.length = scale * (0.05 + u(rng));
      o.width = scale * (0.05 + u(rng));
      const Vec3 axis = random_unit_or_z(rng);
      const glm::dmat3 r = glm::dmat3(glm::rotate(glm::dmat4(1.0), 2 * kPi * u(rng), axis));
      e = make_emitter(o, Vec3(u(rng), u(rng), u(rng)) * scale, r, dists[k / 64 % 5],
                       3 + int(u(rng) * 30));
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
      p = e.centroid + random_unit_or_z(rng) * size * std::pow(10.0, 4.0 * u(rng));
    }
    Vec3 n = random_unit_or_z(rng);
    if (u(rng) < 0.2) {  // grazing: normal almost in the emitter plane
      n = glm::normalize(glm::cross(e.normal, random_unit_or_z(rng)) +
                         e.normal * (u(rng) - 0.5) * 1e-9);
    }
    // Cheap deterministic models on every configuration; the adaptive ones on a subset.
    double v[4] = {paper_cubature_illuminance(e, p, n), far_field_illuminance(e, p, n), 0.0, 0.0};
    if (k % 16 == 0) {
      v[2] = standard_illuminance(e, p, n);
      v[3] = subdivided_illuminance(e, p, n, 2, TriangleRule::two_kernel);
    }
    for (double x : v)
      if (!(std::isfinite(x) && x >= 0.0)) ++bad;
    if (!e.is_point()) {
      const double d = distance_to_polygon(e, p);
      const double bound = kBoundMargin * i_max[k / 64 % 5] / (d * d);
      if (std::isfinite(bound)) {
        ++bounded;
        for (double x : v)
          if (x > bound) ++above;
      }
    }
    // The raw published cubature (with the shift) must also be finite on its own.
    if (k % 8 == 0) {
      const double raw = paper_cubature_raw(e, p, n, horizon_shift_m(e));
      if (!(std::isfinite(raw) && raw >= 0.0)) ++bad;
    }
  }
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(above, 0) << "of " << bounded << " bounded configurations";
  EXPECT_GT(bounded, kConfigurations / 2);
}

}  // namespace
}  // namespace luxgrid::nearfield
