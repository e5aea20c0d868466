// The table rung's ends step (calc/nearfield/table_rays.h): where each ray from the receiver's
// foot F enters and leaves the opening, and gamma' there. The four-lane version against one ray
// at a time, bit for bit, in each version the multiversioning macro makes; and the step against
// a brute-force reference (every edge intersected, atan of the distance over |sigma|).
#include "calc/nearfield/table_rays.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace luxgrid::nearfield {
namespace {

// A convex polygon (counter-clockwise) from its vertices, with its edges prepared.
Polygon2 polygon(const std::vector<glm::dvec2>& v) {
  Polygon2 p;
  p.n = static_cast<int>(v.size());
  for (int i = 0; i < p.n; ++i) p.v[i] = v[i];
  p.prepare_edges();
  return p;
}

// The distances along the ray from the origin in direction (c, s) to each edge it crosses,
// solved directly (origin + t (c, s) = a + u e by Cramer's rule), with the edges they belong to.
struct Crossing {
  double t;
  int edge;
};
std::vector<Crossing> crossings(const Polygon2& p, double c, double s) {
  std::vector<Crossing> out;
  for (int i = 0; i < p.n; ++i) {
    const glm::dvec2 a = p.v[i], e = p.v[(i + 1) % p.n] - a;
    const double det = -c * e.y + s * e.x;  // of [[c, -e.x], [s, -e.y]]
    if (det == 0.0) continue;
    const double t = (-a.x * e.y + a.y * e.x) / det, u = (c * a.y - s * a.x) / det;
    if (u >= 0.0 && u <= 1.0 && t >= 0.0) out.push_back({t, i});
  }
  return out;
}

// A random convex quadrilateral (a parallelogram, or a sliver of one) away from the origin, and
// rays from the origin through random points of it, each with the edges it enters and leaves
// through (the nearest and farthest crossing).
struct Case {
  Polygon2 poly;
  std::vector<RayJob> jobs;
};
Case random_case(std::mt19937_64& rng, int t) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), w(0.0, 1.0);
  const glm::dvec2 o(2.0 + u(rng), u(rng));
  glm::dvec2 e1(0.5 * u(rng), 0.5 * u(rng)), e2(0.5 * u(rng), 0.5 * u(rng));
  if (t % 5 == 0) e2 = 1e-7 * e1 + glm::dvec2(-e1.y, e1.x) * 1e-6;  // a sliver
  if (e1.x * e2.y - e1.y * e2.x < 0.0) std::swap(e1, e2);           // counter-clockwise
  Case c{polygon({o, o + e1, o + e1 + e2, o + e2}), {}};
  for (int r = 0; r < 4; ++r) {
    const double a = w(rng), b = w(rng);
    glm::dvec2 q = o + a * e1 + b * e2;
    if ((t + r) % 7 == 0) q = o + 0.5 * e1;  // through an edge's middle
    const double len = glm::length(q);
    const double cs = q.x / len, sn = q.y / len;
    const std::vector<Crossing> x = crossings(c.poly, cs, sn);
    int near = -1, far = -1;
    double t_near = 1e300, t_far = -1.0;
    for (const Crossing& k : x) {
      if (k.t < t_near) t_near = k.t, near = k.edge;
      if (k.t > t_far) t_far = k.t, far = k.edge;
    }
    RayJob job{};
    job.psi = std::atan2(sn, cs), job.c = cs, job.s = sn, job.scale = 1.0;
    job.near_edge = near, job.far_edge = far;
    c.jobs.push_back(job);
  }
  return c;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_ends(const RayEnds& a, const RayEnds& b) {
  if (a.ok != b.ok) return false;
  if (!a.ok) return true;  // the rest is not used
  return same_bits(a.sin_near, b.sin_near) && same_bits(a.cos_near, b.cos_near) &&
         same_bits(a.sin_far, b.sin_far) && same_bits(a.cos_far, b.cos_far) &&
         same_bits(a.tan_near, b.tan_near) && same_bits(a.tan_far, b.tan_far) &&
         same_bits(a.g_near, b.g_near) && same_bits(a.g_far, b.g_far);
}

using Ends4 = void (*)(const Polygon2&, const RayJob*, double, RayEnds*);
void expect_four_same_bits_as_one_by_one(Ends4 ends4) {
  std::mt19937_64 rng(35);
  std::uniform_real_distribution<double> sigma(-3.0, 3.0);
  int differ = 0, ok = 0, tried = 0;
  for (int t = 0; t < 20000; ++t) {
    const Case c = random_case(rng, t);
    bool known = true;
    for (const RayJob& j : c.jobs) known = known && j.near_edge >= 0 && j.far_edge >= 0;
    if (!known) continue;
    ++tried;
    double s = sigma(rng);
    if (t % 9 == 0) s = 1e-9;  // the receiver almost in the emitter's plane
    const double inv_sigma = 1.0 / std::abs(s);
    RayEnds four[4], one[4];
    ends4(c.poly, c.jobs.data(), inv_sigma, four);
    for (int l = 0; l < 4; ++l) {
      ray_ends(c.poly, false, inv_sigma, &c.jobs[l], 1, &one[l]);  // one ray: no lanes
      differ += !same_ends(four[l], one[l]);
      ok += one[l].ok;
    }
  }
  EXPECT_EQ(differ, 0);
  EXPECT_GT(tried, 15000);
  EXPECT_GT(ok, 3 * tried);  // most rays reach the opening
}

TEST(TableRays, FourEndsSameBitsAsOneByOneAvx2) {
  if (!simd::cpu_has_avx2()) GTEST_SKIP() << "this processor has no AVX2";
  expect_four_same_bits_as_one_by_one(ends_by_edges4_avx2);
}
TEST(TableRays, FourEndsSameBitsAsOneByOneDefault) {
  expect_four_same_bits_as_one_by_one(ends_by_edges4_default);
}

// The ends step against the brute force: for rays through known edges and for rays that try
// every edge (near_edge -1), with F outside and inside the opening, tan(gamma') at both ends is
// the crossing's distance over |sigma| (relative 1e-12: the two solve the same 2 x 2 system in a
// different order; slivers are left out, where that order moves the last digits further), and
// gamma', sin and cos follow from it (1e-14 absolute: the table angle is atan to a few units in
// the last place).
TEST(TableRays, EndsAreTheCrossingsOfTheOutline) {
  std::mt19937_64 rng(36);
  std::uniform_real_distribution<double> sigma(0.2, 3.0), u(-1.0, 1.0);
  int checked = 0;
  for (int t = 0; t < 5000; ++t) {
    Case c = random_case(rng, 1);  // t = 1: no sliver
    const bool inside = t % 2 == 1;
    if (inside) {  // the same shape moved around the origin, rays all around
      glm::dvec2 mid(0.0);
      for (int i = 0; i < c.poly.n; ++i) mid += 0.25 * c.poly.v[i];
      std::vector<glm::dvec2> v;
      for (int i = 0; i < c.poly.n; ++i) v.push_back(c.poly.v[i] - mid);
      c.poly = polygon(v);
      for (RayJob& j : c.jobs) {
        const double psi = kPi * u(rng);
        j.psi = psi, j.c = std::cos(psi), j.s = std::sin(psi);
        j.near_edge = j.far_edge = -1;
      }
    } else if (t % 4 == 0) {
      for (RayJob& j : c.jobs) j.near_edge = j.far_edge = -1;
    }
    const double s = sigma(rng), inv_sigma = 1.0 / s;
    std::vector<RayEnds> ends(c.jobs.size());
    ray_ends(c.poly, inside, inv_sigma, c.jobs.data(), c.jobs.size(), ends.data());
    for (size_t r = 0; r < c.jobs.size(); ++r) {
      const std::vector<Crossing> x = crossings(c.poly, c.jobs[r].c, c.jobs[r].s);
      double t_near = inside ? 0.0 : 1e300, t_far = 0.0;
      for (const Crossing& k : x) t_near = std::min(t_near, k.t), t_far = std::max(t_far, k.t);
      if (x.empty() || !(t_far > t_near * (1.0 + 1e-9))) continue;  // grazing: no reference
      ASSERT_TRUE(ends[r].ok) << t << " " << r;
      const RayEnds& e = ends[r];
      const double tan_near = t_near / s, tan_far = t_far / s;
      EXPECT_NEAR(e.tan_near, tan_near, 1e-12 * tan_far);
      EXPECT_NEAR(e.tan_far, tan_far, 1e-12 * tan_far);
      for (const auto& [tan, g, sin, cos] : {std::array{tan_near, e.g_near, e.sin_near, e.cos_near},
                                             std::array{tan_far, e.g_far, e.sin_far, e.cos_far}}) {
        EXPECT_NEAR(g, std::atan(tan), 1e-14);
        EXPECT_NEAR(sin, std::sin(std::atan(tan)), 1e-14);
        EXPECT_NEAR(cos, std::cos(std::atan(tan)), 1e-14);
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 15000);
}

}  // namespace
}  // namespace luxgrid::nearfield
