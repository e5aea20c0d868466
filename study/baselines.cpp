// Baselines for the accuracy-versus-time study ([Luksch2020, Sec. 4]; docs/accuracy.md):
// structured sampling, the most representative point, and Monte Carlo.
#include "study/baselines.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "calc/nearfield/fan_sample.h"
#include "calc/nearfield/models.h"
#include "geometry/spherical.h"

namespace luxgrid::study {

using nearfield::build_fan;
using nearfield::clip_to_horizon;
using nearfield::Emitter;
using nearfield::FanSample;
using nearfield::far_field_illuminance;
using nearfield::horizon_shift_m;
using nearfield::kMaxPolygonVertices;
using nearfield::OpeningPolygon;
using nearfield::ReceiverFan;
using nearfield::SampleContext;
using nearfield::sanitize_illuminance;

namespace {

double polygon_solid_angle(const std::array<Vec3, kMaxPolygonVertices>& u, int n) {
  double omega = 0.0;
  for (int i = 1; i + 1 < n; ++i) omega += geometry::triangle_solid_angle(u[0], u[i], u[i + 1]);
  return omega;
}

// Closest point of the clipped opening (relative coordinates, in the emitter plane) to `q`.
Vec3 closest(const OpeningPolygon& p, const Vec3& q, const Vec3& plane_normal) {
  return geometry::closest_point(p, q, plane_normal).point;
}

struct Prepared {
  ReceiverFan fan;
  OpeningPolygon poly;  // clipped polygon relative to the shifted receiver
  double s = 0.0;       // signed plane distance of the shifted receiver
};

bool prepare(const Emitter& e, const Vec3& point, const Vec3& normal, Prepared& p) {
  p.fan = build_fan(e, point, normal, horizon_shift_m(e));
  if (p.fan.triangles == 0) return false;
  p.poly = clip_to_horizon(e, p.fan.receiver, normal);
  p.s = glm::dot(p.fan.receiver - e.centroid, e.normal);
  return p.poly.n >= 3;
}

// SplitMix64: a small, fixed, portable generator, so studies are reproducible.
struct SplitMix64 {
  std::uint64_t state;
  double next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
  }
};

// Interior angle of the spherical triangle at unit vertex a (between arcs a->b and a->c).
double vertex_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 tb = b - glm::dot(a, b) * a, tc = c - glm::dot(a, c) * a;
  const double lb = glm::length(tb), lc = glm::length(tc);
  if (!(lb > 0.0) || !(lc > 0.0)) return 0.0;
  return angle_between(tb / lb, tc / lc);
}

// Arvo 1995, "Stratified sampling of spherical triangles": a direction uniformly distributed in
// the solid angle of the triangle (a, b, c) for (u1, u2) in [0, 1)^2.
Vec3 sample_spherical_triangle(const Vec3& a, const Vec3& b, const Vec3& c, double u1, double u2) {
  const double alpha = vertex_angle(a, b, c), beta = vertex_angle(b, c, a),
               gamma = vertex_angle(c, a, b);
  const double area = alpha + beta + gamma - kPi;
  const double area_hat = u1 * area;
  const double s = std::sin(area_hat - alpha), t = std::cos(area_hat - alpha);
  const double u = t - std::cos(alpha);
  const double v = s + std::sin(alpha) * glm::dot(a, b);
  const double den = (v * s + u * t) * std::sin(alpha);
  double q = den != 0.0 ? ((v * t - u * s) * std::cos(alpha) - v) / den : 1.0;
  q = std::clamp(q, -1.0, 1.0);
  Vec3 perp_c = c - glm::dot(c, a) * a;
  const double lpc = glm::length(perp_c);
  perp_c = lpc > 0.0 ? perp_c / lpc : Vec3(0.0);
  const Vec3 c_hat = q * a + safe_sqrt(1.0 - q * q) * perp_c;
  const double z = 1.0 - u2 * (1.0 - glm::dot(c_hat, b));
  Vec3 perp_b = c_hat - glm::dot(c_hat, b) * b;
  const double lpb = glm::length(perp_b);
  perp_b = lpb > 0.0 ? perp_b / lpb : Vec3(0.0);
  return glm::normalize(z * b + safe_sqrt(1.0 - z * z) * perp_b);
}

}  // namespace

double structured_sampling_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal) {
  if (e.is_point()) return far_field_illuminance(e, point, normal);
  Prepared p;
  if (!prepare(e, point, normal, p)) return 0.0;
  const SampleContext sample(e, p.fan);
  std::array<Vec3, kMaxPolygonVertices> u;
  Vec3 centre{0.0};
  double sum = 0.0;
  for (int i = 0; i < p.poly.n; ++i) {
    const FanSample f = sample(p.poly.v[i]);
    u[i] = f.w;
    sum += f.L * f.G;
    centre += p.poly.v[i];
  }
  const FanSample c = sample(centre / double(p.poly.n));
  sum += c.L * c.G;
  // Eq. 4 without rho/pi: E = Omega / N sum L_e G.
  return sanitize_illuminance(polygon_solid_angle(u, p.poly.n) / (p.poly.n + 1) * sum);
}

double mrp_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal) {
  if (e.is_point()) return far_field_illuminance(e, point, normal);
  Prepared p;
  if (!prepare(e, point, normal, p)) return 0.0;
  const SampleContext sample(e, p.fan);
  const Vec3 nA = e.normal;
  // Plane through the polygon, relative coordinates: points r with r . nA = -s.
  auto onto_plane = [&](const Vec3& dir) -> Vec3 {  // intersection of the ray, or its far end
    const double dn = glm::dot(dir, nA);
    if (std::abs(dn) > 1e-12 && -p.s / dn > 0.0) return dir * (-p.s / dn);
    const Vec3 in_plane = dir - dn * nA;
    return in_plane * (1e6 * e.largest_dimension_m) / std::max(glm::length(in_plane), 1e-300) -
           p.s * nA;
  };
  const Vec3 cp = closest(p.poly, -p.s * nA, nA);
  const Vec3 np = closest(p.poly, onto_plane(normal), nA);
  const Vec3 half = glm::normalize(glm::normalize(cp) + glm::normalize(np));
  const Vec3 mrp = closest(p.poly, onto_plane(half), nA);
  const double projected = geometry::projected_solid_angle(p.poly.v.data(), p.poly.n, normal);
  return sanitize_illuminance(sample(mrp).L * projected);
}

double monte_carlo_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal, int samples,
                               std::uint64_t seed) {
  if (e.is_point()) return far_field_illuminance(e, point, normal);
  Prepared p;
  if (!prepare(e, point, normal, p)) return 0.0;
  const SampleContext sample(e, p.fan);
  const int m = p.fan.triangles;
  std::array<Vec3, kMaxPolygonVertices + 1> u;
  std::array<double, kMaxPolygonVertices + 1> cdf;
  const Vec3 apex = glm::normalize(p.fan.apex);
  for (int i = 0; i <= m; ++i) u[i] = glm::normalize(p.fan.rim[i]);
  double omega = 0.0;
  for (int i = 0; i < m; ++i) {
    omega += geometry::triangle_solid_angle(apex, u[i], u[i + 1]);
    cdf[i] = omega;
  }
  if (!(omega > 0.0)) return 0.0;
  SplitMix64 rng{seed * 0x2545F4914F6CDD1DULL + 1};
  const double nA_abs_inv = 1.0 / e.area_m2;
  double sum = 0.0;
  for (int k = 0; k < samples; ++k) {
    // Stratified choice of the triangle (by solid angle), then Arvo inside it.
    const double x = (k + rng.next()) / samples * omega;
    int t = 0;
    while (t + 1 < m && cdf[t] < x) ++t;
    const Vec3 w = sample_spherical_triangle(apex, u[t], u[t + 1], rng.next(), rng.next());
    const double cos_e = std::abs(glm::dot(w, e.normal));
    const double g = glm::dot(w, normal);
    if (!(cos_e > 0.0) || !(g > 0.0)) continue;
    sum += e.intensity_towards(-w) * nA_abs_inv / cos_e * g;
  }
  return sanitize_illuminance(omega * sum / samples);
}

}  // namespace luxgrid::study
