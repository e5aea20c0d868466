// Property test of the near-field hot path: the horizon clip and the closest
// point of calc/nearfield/receiver_fan.cpp, in plain double arithmetic, against the same
// operations done with CGAL's exact-constructions kernel on random convex polygons and planes,
// plus degenerate set-ups whose coordinates are exact in binary so the exact answer is the
// true one (plane through a vertex, plane along an edge, polygon in the horizon plane, tiny and
// huge scales).
//
// CGAL is header-only; with GMP disabled Epeck runs on boost::multiprecision::cpp_rational, so
// this test needs CGAL's headers (in /usr/include) but no extra library on nearfield_tests.
#define CGAL_DISABLE_GMP 1
#define CGAL_DISABLE_MPFR 1
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/squared_distance_3.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "calc/nearfield/emitter.h"
#include "calc/nearfield/receiver_fan.h"

namespace luxgrid::nearfield {
namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using XPoint = K::Point_3;
using XVector = K::Vector_3;
using XSegment = K::Segment_3;
using XPlane = K::Plane_3;
using XTriangle = K::Triangle_3;
using FT = K::FT;

// Tolerances, relative to the emitter's size L (lengths) or L^2 (areas). Every hot-path value is
// a handful of double operations on coordinates of size ~L from a receiver at distance ~L, so
// its rounding error is ~1e-15 L; 1e-9 leaves six orders of margin and still catches any wrong
// vertex, wrong crossing or wrong clamp, which are errors of order L.
constexpr double kLengthTol = 1e-9;
constexpr double kAreaTol = 1e-9;

XPoint to_exact(const Vec3& p) { return XPoint(p.x, p.y, p.z); }
XVector to_exact_v(const Vec3& v) { return XVector(v.x, v.y, v.z); }
double to_d(const FT& x) { return CGAL::to_double(x); }

// Emitter from a convex polygon, counter-clockwise about `normal` (the hot path's convention),
// without make_polygon_emitter's planarity check so exact-in-binary set-ups stay exact.
Emitter polygon_emitter(const std::vector<Vec3>& v, const Vec3& normal) {
  Emitter e;
  e.vertices = v;
  Vec3 c(0.0);
  for (const Vec3& p : v) c += p;
  e.centroid = c / static_cast<double>(v.size());
  e.normal = normal;
  // The largest vertex-to-vertex distance, as make_emitter computes it (left at 0 it
  // would zero the horizon shift).
  for (const Vec3& a : v)
    for (const Vec3& b : v)
      e.largest_dimension_m = std::max(e.largest_dimension_m, glm::length(a - b));
  double area2 = 0.0;
  for (size_t i = 1; i + 1 < v.size(); ++i)
    area2 += glm::dot(glm::cross(v[i] - v[0], v[i + 1] - v[0]), normal);
  e.area_m2 = 0.5 * area2;
  return e;
}

// Exact Sutherland-Hodgman with CGAL predicates and constructions, receiver-relative.
std::vector<XPoint> exact_clip(const Emitter& e, const Vec3& point, const Vec3& normal) {
  const XPoint origin = CGAL::ORIGIN;
  const XVector pt = to_exact_v(point);
  std::vector<XPoint> rel;
  for (const Vec3& v : e.vertices) rel.push_back(to_exact(v) - pt);
  const XPlane horizon(origin, to_exact_v(normal));
  std::vector<XPoint> out;
  const size_t n = rel.size();
  for (size_t i = 0; i < n; ++i) {
    const XPoint& a = rel[i];
    const XPoint& b = rel[(i + 1) % n];
    const CGAL::Oriented_side sa = horizon.oriented_side(a);
    const CGAL::Oriented_side sb = horizon.oriented_side(b);
    if (sa != CGAL::ON_NEGATIVE_SIDE) out.push_back(a);
    if ((sa == CGAL::ON_POSITIVE_SIDE && sb == CGAL::ON_NEGATIVE_SIDE) ||
        (sa == CGAL::ON_NEGATIVE_SIDE && sb == CGAL::ON_POSITIVE_SIDE)) {
      const auto hit = CGAL::intersection(XSegment(a, b), horizon);
      const XPoint* p = hit ? boost::get<XPoint>(&*hit) : nullptr;
      EXPECT_NE(p, nullptr) << "a crossing edge must meet the plane in one point";
      if (p) out.push_back(*p);
    }
  }
  return out;
}

// |vector area| of a planar polygon (exact), 0 for fewer than three vertices.
double exact_area(const std::vector<XPoint>& p) {
  if (p.size() < 3) return 0.0;
  XVector s(0, 0, 0);
  for (size_t i = 1; i + 1 < p.size(); ++i)
    s = s + CGAL::cross_product(p[i] - p[0], p[i + 1] - p[0]);
  return 0.5 * std::sqrt(to_d(s.squared_length()));
}

double fast_area(const OpeningPolygon& p) {
  if (p.n < 3) return 0.0;
  Vec3 s(0.0);
  for (int i = 1; i + 1 < p.n; ++i) s += glm::cross(p.v[i] - p.v[0], p.v[i + 1] - p.v[0]);
  return 0.5 * glm::length(s);
}

// Distance from q to the boundary of a polygon (exact squared distances to its edges).
double distance_to_boundary(const XPoint& q, const std::vector<XPoint>& poly) {
  if (poly.empty()) return INFINITY;
  if (poly.size() == 1) return std::sqrt(to_d(CGAL::squared_distance(q, poly[0])));
  FT best = CGAL::squared_distance(q, XSegment(poly[0], poly[1 % poly.size()]));
  for (size_t i = 1; i < poly.size(); ++i)
    best =
        std::min(best, CGAL::squared_distance(q, XSegment(poly[i], poly[(i + 1) % poly.size()])));
  return std::sqrt(to_d(best));
}

// Exact closest point of a convex planar polygon to the origin (the receiver): the foot of the
// origin on the polygon's plane when inside, else the nearest point of the nearest edge.
XPoint exact_closest_point(const std::vector<XPoint>& poly, const XVector& plane_normal) {
  const XPoint o = CGAL::ORIGIN;
  const XPlane plane(poly[0], plane_normal);
  const XPoint foot = plane.projection(o);
  bool inside = true;
  for (size_t i = 0; i < poly.size() && inside; ++i) {
    const XVector edge = poly[(i + 1) % poly.size()] - poly[i];
    if (CGAL::cross_product(edge, foot - poly[i]) * plane_normal < 0) inside = false;
  }
  if (inside) return foot;
  XPoint best_p = poly[0];
  FT best = CGAL::squared_distance(o, best_p);
  for (size_t i = 0; i < poly.size(); ++i) {
    const XPoint a = poly[i];
    const XVector ab = poly[(i + 1) % poly.size()] - a;
    const FT len2 = ab.squared_length();
    if (len2 == 0) continue;
    FT t = ((foot - a) * ab) / len2;
    t = std::clamp(t, FT(0), FT(1));
    const XPoint p = a + t * ab;
    const FT d = CGAL::squared_distance(o, p);
    if (d < best) {
      best = d;
      best_p = p;
    }
  }
  return best_p;
}

// Checks clip_to_horizon and build_fan (shift 0 so the receiver is the given point) against the
// exact computation. `what` names the case in failure messages.
void check_against_exact(const Emitter& e, const Vec3& point, const Vec3& normal,
                         const std::string& what) {
  SCOPED_TRACE(what);
  const double L = e.largest_dimension_m;
  const double tol = kLengthTol * std::max(L, glm::length(e.centroid - point));
  const OpeningPolygon fast = clip_to_horizon(e, point, normal);
  ASSERT_LE(fast.n, kMaxPolygonVertices);
  ASSERT_LE(fast.n, static_cast<int>(e.vertices.size()) + 1) << "a convex clip adds one vertex";
  const std::vector<XPoint> exact = exact_clip(e, point, normal);

  // Every vertex the hot path keeps is on the visible side and in the emitter's plane.
  for (int i = 0; i < fast.n; ++i) {
    EXPECT_GE(glm::dot(fast.v[i], normal), -tol) << "vertex " << i << " below the horizon";
    EXPECT_NEAR(glm::dot(fast.v[i] + point - e.centroid, e.normal), 0.0, tol)
        << "vertex " << i << " off the emitter plane";
  }
  // Same region: equal areas, and each polygon's vertices lie on the other's boundary (a
  // Hausdorff check on convex polygons whose vertex lists may differ by duplicates).
  const double scale2 = std::max(L * L, e.area_m2);
  EXPECT_NEAR(fast_area(fast), exact_area(exact), kAreaTol * scale2);
  if (fast.n >= 3 && exact.size() >= 3) {
    std::vector<XPoint> fast_x;
    for (int i = 0; i < fast.n; ++i) fast_x.push_back(to_exact(fast.v[i]));
    for (size_t i = 0; i < fast_x.size(); ++i)
      EXPECT_LE(distance_to_boundary(fast_x[i], exact), tol) << "fast vertex " << i;
    for (size_t i = 0; i < exact.size(); ++i)
      EXPECT_LE(distance_to_boundary(exact[i], fast_x), tol) << "exact vertex " << i;
  } else {
    // One side sees (almost) nothing: then the other's vertices are all within rounding of
    // the horizon plane.
    for (const XPoint& p : exact) EXPECT_LE(to_d((p - CGAL::ORIGIN) * to_exact_v(normal)), tol);
    for (int i = 0; i < fast.n; ++i) EXPECT_LE(glm::dot(fast.v[i], normal), tol);
  }

  // Closest point and fan, shift disabled: fan.receiver == point.
  const ReceiverFan fan = build_fan(e, point, normal, 0.0);
  if (fast.n < 3) {
    EXPECT_EQ(fan.triangles, 0);
    return;
  }
  if (exact.size() < 3) return;  // rounding-thin sliver: nothing exact to compare with
  const XPoint cp = exact_closest_point(exact, to_exact_v(e.normal));
  const Vec3 cp_d(to_d(cp.x()), to_d(cp.y()), to_d(cp.z()));
  EXPECT_LE(glm::length(fan.apex - cp_d), tol)
      << "closest point, case " << static_cast<int>(fan.cp_case);
  EXPECT_NEAR(glm::length(fan.apex),
              std::sqrt(to_d(CGAL::squared_distance(XPoint(CGAL::ORIGIN), cp))), tol);
  // CGAL's own point-triangle distance over a fan of the exact polygon agrees too.
  FT d2 = CGAL::squared_distance(XPoint(CGAL::ORIGIN), XTriangle(exact[0], exact[1], exact[2]));
  for (size_t i = 2; i + 1 < exact.size(); ++i)
    d2 = std::min(d2, CGAL::squared_distance(XPoint(CGAL::ORIGIN),
                                             XTriangle(exact[0], exact[i], exact[i + 1])));
  EXPECT_NEAR(glm::length(fan.apex), std::sqrt(to_d(d2)), tol);
  // The fan around CP tiles the clipped polygon: its triangles' areas add up to the polygon's.
  double fan_area = 0.0;
  for (int i = 0; i < fan.triangles; ++i)
    fan_area += 0.5 * glm::length(glm::cross(fan.rim[i] - fan.apex, fan.rim[i + 1] - fan.apex));
  EXPECT_NEAR(fan_area, exact_area(exact), kAreaTol * scale2);
  const int expected_triangles = fan.cp_case == ClosestPointCase::inside ? fast.n
                                 : fan.cp_case == ClosestPointCase::edge ? fast.n - 1
                                                                         : fast.n - 2;
  EXPECT_EQ(fan.triangles, expected_triangles);
}

// A random convex polygon: n points at sorted random angles on an ellipse in the plane through
// `centre` with unit normal `normal`, counter-clockwise about it.
std::vector<Vec3> random_convex_polygon(std::mt19937_64& rng, int n, const Vec3& centre,
                                        const Vec3& normal, double size) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const Vec3 helper = std::abs(normal.x) < 0.9 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
  const Vec3 a = glm::normalize(glm::cross(normal, helper));
  const Vec3 b = glm::cross(normal, a);  // (a, b, normal) right-handed: CCW about normal
  std::vector<double> angles(n);
  for (double& t : angles) t = 2.0 * kPi * u01(rng);
  std::sort(angles.begin(), angles.end());
  const double ra = size * (0.2 + u01(rng)), rb = size * (0.2 + u01(rng));
  std::vector<Vec3> v;
  for (double t : angles) v.push_back(centre + ra * std::cos(t) * a + rb * std::sin(t) * b);
  return v;
}

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  Vec3 v(g(rng), g(rng), g(rng));
  while (glm::length(v) < 1e-3) v = Vec3(g(rng), g(rng), g(rng));
  return glm::normalize(v);
}

TEST(HotPathVsCgal, RandomPolygonsAndPlanesAtEveryScale) {
  std::mt19937_64 rng(20260611);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> sides(3, 40);
  for (double scale : {1e-6, 1e-3, 1.0, 1e3, 1e6}) {
    for (int trial = 0; trial < 150; ++trial) {
      const Vec3 en = random_unit(rng);
      const Vec3 centre = scale * Vec3(u(rng), u(rng), u(rng));
      const Emitter e =
          polygon_emitter(random_convex_polygon(rng, sides(rng), centre, en, scale), en);
      // Receivers near (plane cuts the polygon often) and far from the emitter.
      const double reach = (trial % 2 ? 0.5 : 3.0) * scale;
      const Vec3 point = centre + reach * Vec3(u(rng), u(rng), u(rng));
      check_against_exact(e, point, random_unit(rng),
                          "scale " + std::to_string(scale) + " trial " + std::to_string(trial));
    }
  }
}

TEST(HotPathVsCgal, PlaneThroughAVertex) {
  // Receiver exactly at a vertex (relative coordinates exactly 0) and random normals; and a
  // receiver elsewhere whose axis-aligned horizon passes exactly through a vertex.
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> sides(3, 12);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 en = random_unit(rng);
    const Emitter e =
        polygon_emitter(random_convex_polygon(rng, sides(rng), Vec3(0.3, -0.2, 2.0), en, 1.0), en);
    const Vec3& vtx = e.vertices[trial % e.vertices.size()];
    check_against_exact(e, vtx, random_unit(rng), "at vertex, trial " + std::to_string(trial));
    // Horizon z = vtx.z exactly (an axis-aligned normal keeps h exact in binary).
    const Vec3 point(vtx.x + 0.75, vtx.y - 1.5, vtx.z);
    check_against_exact(e, point, Vec3(0.0, 0.0, trial % 2 ? 1.0 : -1.0),
                        "horizon through vertex, trial " + std::to_string(trial));
  }
}

TEST(HotPathVsCgal, PlaneAlongAnEdge) {
  // Integer polygons in the plane x + y + z = 6 (exactly planar in binary) with horizontal
  // edges (direction (1, -1, 0)); the horizon z = c passes exactly along such an edge.
  const Vec3 en = glm::normalize(Vec3(1.0, 1.0, 1.0));
  // Hexagon with z levels 0, 0, 2, 4, 4, 2: CCW about (1, 1, 1).
  const std::vector<Vec3> hexagon = {{4, 2, 0}, {2, 4, 0}, {0, 4, 2},
                                     {0, 2, 4}, {2, 0, 4}, {4, 0, 2}};
  const Emitter e = polygon_emitter(hexagon, en);
  ASSERT_GT(e.area_m2, 0.0) << "hexagon must be counter-clockwise about its normal";
  for (double z : {0.0, 4.0}) {
    for (double sign : {1.0, -1.0}) {
      for (const Vec3& offset : {Vec3(5, -3, 0), Vec3(-1, -1, 0), Vec3(2, 2, 0)}) {
        const Vec3 point = offset + Vec3(0.0, 0.0, z);
        check_against_exact(e, point, Vec3(0.0, 0.0, sign),
                            "along edge z=" + std::to_string(z) + " sign " + std::to_string(sign));
      }
    }
  }
  // Through the two middle vertices (z = 2): the clip keeps them once each.
  const OpeningPolygon half = clip_to_horizon(e, Vec3(1.0, 1.0, 2.0), Vec3(0.0, 0.0, 1.0));
  EXPECT_EQ(half.n, 4);
}

TEST(HotPathVsCgal, PolygonInTheHorizonPlane) {
  // Axis-aligned: every h is exactly 0, the closed half-space keeps the whole polygon, and CP
  // is the foot (the receiver is in the plane, so the fan apex is the receiver itself).
  std::mt19937_64 rng(11);
  for (int n : {3, 4, 17, kMaxDiskSegments}) {
    const Vec3 up(0.0, 0.0, 1.0);
    const Emitter e =
        polygon_emitter(random_convex_polygon(rng, n, Vec3(0.0, 0.0, 3.0), up, 1.0), up);
    for (const Vec3& point : {Vec3(0.0, 0.0, 3.0), Vec3(5.0, 1.0, 3.0)}) {
      const OpeningPolygon p = clip_to_horizon(e, point, up);
      EXPECT_EQ(p.n, n);
      check_against_exact(e, point, up, "coplanar n=" + std::to_string(n));
      check_against_exact(e, point, -up, "coplanar, facing away, n=" + std::to_string(n));
    }
  }
}

TEST(HotPathVsCgal, TiltedPolygonNearlyInTheHorizonPlaneStaysInCapacity) {
  // A tilted 128-gon with the receiver in its plane and the normal equal to the emitter's: in
  // doubles the heights are +-rounding and their signs alternate arbitrarily, the one set-up
  // where a clip could emit more vertices than a convex clip can. The hot path must stay within
  // its fixed capacity and keep only points within rounding of the horizon. (build_fan itself
  // never sees this: the horizon shift moves the receiver 1e-6 L off the plane.)
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 50; ++trial) {
    const Vec3 en = random_unit(rng);
    const Vec3 centre(1.25, -0.5, 2.0);
    const Emitter e =
        polygon_emitter(random_convex_polygon(rng, kMaxDiskSegments, centre, en, 1.0), en);
    const OpeningPolygon p = clip_to_horizon(e, e.vertices[5], en);
    ASSERT_LE(p.n, static_cast<int>(e.vertices.size()) + 1) << "trial " << trial;
    for (int i = 0; i < p.n; ++i) EXPECT_NEAR(glm::dot(p.v[i], en), 0.0, 1e-12);
    // With the shift the receiver leaves the plane to the side its rounded distance has: in
    // front it faces away (nothing visible); behind, it sees the whole back of the polygon.
    const ReceiverFan fan = build_fan(e, e.vertices[5], en, horizon_shift_m(e));
    if (fan.front)
      EXPECT_EQ(fan.triangles, 0) << "trial " << trial << " plane distance " << fan.plane_distance
                                  << " shift " << horizon_shift_m(e) << " cp case "
                                  << static_cast<int>(fan.cp_case);
    else
      EXPECT_GE(fan.triangles, kMaxDiskSegments - 2) << "trial " << trial;
    EXPECT_LE(fan.triangles, kMaxDiskSegments) << "trial " << trial;
  }
}

}  // namespace
}  // namespace luxgrid::nearfield
