// Lambert's polygon formula (geometry/spherical.h) as the exact form factor of calc/indirect
// (form_factor.h), after its arcs came from the table angle (util/table_angle.h) and its corners
// stayed unnormalised: against the formula as it was written before (normalised corners, the
// library's atan2, the sum as a vector) and against the closed box's identity (the factors of
// every patch of a closed room add up to 1 from any point inside it). Tiny patches, where each
// arc's sine is tiny and theta / sin tends to 1, against Hottel's closed form: indirect_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "calc/indirect/form_factor.h"
#include "geometry/polygon3.h"
#include "geometry/spherical.h"

namespace luxgrid::calc::indirect {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// The formula as it stood before the table angle: unit corners, theta = atan2(|a x b|, a . b),
// the sum of theta (a x b) / |a x b| as a vector, projected at the end.
double reference_psa(const Vec3* rel, int count, const Vec3& n) {
  std::vector<Vec3> u;
  for (int k = 0; k < count; ++k) {
    const double len = glm::length(rel[k]);
    if (len > geometry::kMinCornerDistance_m) u.push_back(rel[k] / len);
  }
  if (count < 3 || u.empty()) return 0.0;
  Vec3 sum(0.0);
  for (size_t k = 0; k < u.size(); ++k) {
    const Vec3 c = glm::cross(u[k], u[(k + 1) % u.size()]);
    const double s = glm::length(c);
    if (!(s > 0.0)) continue;
    const double theta = std::atan2(s, glm::dot(u[k], u[(k + 1) % u.size()]));
    sum += c * (theta / s);
  }
  return 0.5 * std::abs(glm::dot(n, sum));
}

double reference_form_factor(const Vec3& x, const Vec3& n, const Polygon3& polygon) {
  const auto clipped = geometry::clip_to_half_space_relative<32>(
      polygon.data(), static_cast<int>(polygon.size()), x, n);
  return std::clamp(reference_psa(clipped.v.data(), clipped.n, n) / kPi, 0.0, 1.0);
}

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return glm::normalize(Vec3(g(rng), g(rng), g(rng)));
}

// Random planar convex polygons (3 to 8 corners on an ellipse, turned at random) from points at
// every distance, from touching to 10^4 sizes away, with every normal, so that patches are seen
// whole, cut by the horizon, edge-on and behind: the two formulas agree within 4 x 2^-52,
// absolute (the largest seen is 2.5). Absolute, not relative: each edge rounds on the scale of
// its unit vectors' cross product, so a small factor, a small difference of its edges, keeps
// that rounding (both formulas alike; tiny patches: indirect_test.cpp).
TEST(Lambert, AgreesWithTheFormulaWithNormalisedCornersAndAtan2) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  int compared = 0;
  for (int i = 0; i < 200000; ++i) {
    const int corners = 3 + static_cast<int>(unit(rng) * 6);
    const Vec3 axis = random_unit(rng);
    const Vec3 e1 = glm::normalize(glm::cross(axis, random_unit(rng)));
    const Vec3 e2 = glm::cross(axis, e1);
    const double a = 0.05 + unit(rng), b = 0.05 + unit(rng);
    Polygon3 polygon;
    for (int k = 0; k < corners; ++k) {
      const double t = 2.0 * kPi * (k + 0.3 * unit(rng)) / corners;
      polygon.push_back(a * std::cos(t) * e1 + b * std::sin(t) * e2);
    }
    const double distance = std::max(a, b) * std::pow(10.0, -3.0 + 7.0 * unit(rng));
    const Vec3 x = distance * random_unit(rng);
    const Vec3 n = random_unit(rng);
    const double want = reference_form_factor(x, n, polygon);
    const double got = point_polygon_form_factor(x, n, polygon);
    const double err = std::abs(got - want) / kEps;
    worst = std::max(worst, err);
    ++compared;
    ASSERT_LE(err, 4.0) << "case " << i << ": " << got << " against " << want;
  }
  std::printf("[ lambert ] %d factors: largest difference %.2f x 2^-52\n", compared, worst);
}

// A point inside a closed box sees every direction of its hemisphere through exactly one patch:
// the patches' factors add up to 1 (the cosine-weighted hemisphere, pi, over pi), whatever the
// point, its normal or the mesh. Points anywhere inside, 1 mm from a wall and at a corner; every
// patch near, far, cut by the horizon, seen edge-on or from behind (factor 0).
TEST(Lambert, FactorsOfAClosedBoxAddUpToOne) {
  const double w = 4.0, d = 3.0, h = 2.8, size = 0.35;
  std::vector<Polygon3> patches;
  // A face from origin o along u (length lu) and v (length lv), cut into cells of about `size`,
  // corners counter-clockwise seen from inside (the order does not matter to the factor).
  auto face = [&](const Vec3& o, const Vec3& u, double lu, const Vec3& v, double lv) {
    const int nu = static_cast<int>(std::ceil(lu / size)),
              nv = static_cast<int>(std::ceil(lv / size));
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j) {
        const Vec3 p = o + u * (lu * i / nu) + v * (lv * j / nv);
        const Vec3 du = u * (lu / nu), dv = v * (lv / nv);
        patches.push_back({p, p + du, p + du + dv, p + dv});
      }
  };
  const Vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
  face(Vec3(0, 0, 0), X, w, Y, d);  // floor
  face(Vec3(0, 0, h), X, w, Y, d);  // ceiling
  face(Vec3(0, 0, 0), X, w, Z, h);  // walls
  face(Vec3(0, d, 0), X, w, Z, h);
  face(Vec3(0, 0, 0), Y, d, Z, h);
  face(Vec3(w, 0, 0), Y, d, Z, h);
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::pair<Vec3, Vec3>> receivers;
  for (int i = 0; i < 300; ++i)
    receivers.push_back({Vec3(w * unit(rng), d * unit(rng), h * unit(rng)), random_unit(rng)});
  for (int i = 0; i < 100; ++i) {
    // 1 mm in front of the floor, a wall and into a corner, facing into the room (and along it).
    receivers.push_back({Vec3(w * unit(rng), d * unit(rng), 1e-3),
                         glm::normalize(Vec3(unit(rng) - 0.5, unit(rng) - 0.5, 1.0))});
    receivers.push_back({Vec3(1e-3, d * unit(rng), h * unit(rng)), Vec3(1, 0, 0)});
    receivers.push_back(
        {Vec3(1e-3, 1e-3, 1e-3), glm::normalize(Vec3(unit(rng), unit(rng), unit(rng)))});
  }
  double worst = 0.0;
  for (const auto& [x, n] : receivers) {
    double sum = 0.0;
    for (const Polygon3& p : patches) sum += point_polygon_form_factor(x, n, p);
    worst = std::max(worst, std::abs(sum - 1.0));
    ASSERT_NEAR(sum, 1.0, 1e-12) << "at " << x.x << " " << x.y << " " << x.z;
  }
  std::printf("[ lambert ] %zu patches, %zu points: largest |sum - 1| %.2e\n", patches.size(),
              receivers.size(), worst);
}

}  // namespace
}  // namespace luxgrid::calc::indirect
