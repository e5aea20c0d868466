#pragma once
// The per-triangle quadrature rules of the ladder (see models.h, TriangleRule).
#include "calc/nearfield/fan_sample.h"
#include "calc/nearfield/models.h"
#include "geometry/spherical.h"

namespace luxgrid::nearfield {

// [Luksch2020, Eq. 10] without rho / pi (illuminance, not reflected radiance): the product of
// the averages of L and G over the triangle's three nodes, weighted by its solid angle (the
// spherical excess, [Luksch2020, Eq. 11]). The paper cubature and the `paper` rule of the
// subdivided rungs call it.
inline double paper_triangle(const FanSample& a, const FanSample& b, const FanSample& c) {
  return (a.L + b.L + c.L) / 3.0 * ((a.G + b.G + c.G) / 3.0) *
         geometry::triangle_solid_angle(a.w, b.w, c.w);
}

// L average that is exact when both L and the area-form weight rho = cos_r cos_e / d^2 are
// linear over the planar triangle: with barycentric lambda_i, int lambda_i lambda_j dA =
// A (1 + delta_ij) / 12, so int L rho / int rho = (sum L sum rho + sum L rho) / (4 sum rho).
// Near the closest point rho is largest and pulls the average towards the CP's radiance, as the
// projected solid angle there is largest; far away it tends to the plain mean.
inline double product_average(const FanSample& a, const FanSample& b, const FanSample& c) {
  const double s = a.rho + b.rho + c.rho;
  const double sum_l = a.L + b.L + c.L;
  if (!(s > 0.0)) return sum_l / 3.0;
  return (sum_l * s + a.L * a.rho + b.L * b.rho + c.L * c.rho) / (4.0 * s);
}

// Integral over the planar triangle (a, b, c) of cos_r / d^2 dA = n_x . V with
// V = integral of r / |r|^3 dA = grad_x of the triangle's single-layer potential:
//   normal part  -sign(s) Omega n_A      (Omega the solid angle, Van Oosterom-Strackee)
//   in-plane     -sum over edges m_e ln((R_a + R_b + l) / (R_a + R_b - l))
// with m_e the outward in-plane edge normal (divergence theorem in the plane). The log's
// denominator is computed without cancellation: (R_a + R_b)^2 - l^2 = |R_b a + R_a b|^2 / (R_a
// R_b).
inline double isotropic_kernel(const FanSample& a, const FanSample& b, const FanSample& c,
                               const Vec3& normal, const Vec3& plane_normal, double side) {
  const Vec3 area2 = glm::cross(b.r - a.r, c.r - a.r);
  const double orient = glm::dot(area2, plane_normal) >= 0.0 ? 1.0 : -1.0;
  Vec3 v = -side * geometry::triangle_solid_angle(a.w, b.w, c.w) * plane_normal;
  const FanSample* p[3] = {&a, &b, &c};
  for (int i = 0; i < 3; ++i) {
    const FanSample& u = *p[i];
    const FanSample& t = *p[(i + 1) % 3];
    const Vec3 e = t.r - u.r;
    const double l = glm::length(e);
    if (!(l > 0.0)) continue;
    const Vec3 m = orient * glm::cross(e, plane_normal) / l;
    const Vec3 q = t.d * u.r + u.d * t.r;
    const double q2 = glm::dot(q, q);
    if (!(q2 > 0.0)) continue;  // receiver on the edge: excluded by the horizon shift
    const double sum = u.d + t.d + l;
    v -= m * std::log(sum * sum * u.d * t.d / q2);
  }
  return std::max(0.0, glm::dot(normal, v));
}

// I ~ alpha cos_e + beta fitted to the three vertices by least squares; each term integrated
// exactly (alpha: Lambert's projected solid angle, beta: isotropic_kernel), over the area A.
inline double two_kernel_estimate(const FanSample& a, const FanSample& b, const FanSample& c,
                                  const Vec3& normal, const Vec3& plane_normal, double side,
                                  double inv_area) {
  const double cm = (a.cos_e + b.cos_e + c.cos_e) / 3.0, im = (a.I + b.I + c.I) / 3.0;
  const double sxx = (a.cos_e - cm) * (a.cos_e - cm) + (b.cos_e - cm) * (b.cos_e - cm) +
                     (c.cos_e - cm) * (c.cos_e - cm);
  const double sxy =
      (a.cos_e - cm) * (a.I - im) + (b.cos_e - cm) * (b.I - im) + (c.cos_e - cm) * (c.I - im);
  // A fit needs a spread of cos_e (relative, so grazing triangles with cos_e ~ 1e-6 still fit);
  // with all three equal (far away) both kernels agree: K = P / cos_e.
  constexpr double kMinRelativeCosSpread2 = 1e-16;
  const double alpha = sxx > kMinRelativeCosSpread2 * cm * cm ? sxy / sxx : 0.0;
  const double beta = im - alpha * cm;
  double e = 0.0;
  if (alpha != 0.0) e += alpha * geometry::triangle_projected_solid_angle(a.w, b.w, c.w, normal);
  if (beta != 0.0) e += beta * isotropic_kernel(a, b, c, normal, plane_normal, side);
  return std::max(0.0, e * inv_area);
}

inline double triangle_estimate(const FanSample& a, const FanSample& b, const FanSample& c,
                                const SampleContext& ctx, TriangleRule rule) {
  const Vec3& normal = ctx.normal;
  switch (rule) {
    case TriangleRule::paper: return paper_triangle(a, b, c);
    case TriangleRule::lambert_mean:
      return (a.L + b.L + c.L) / 3.0 *
             geometry::triangle_projected_solid_angle(a.w, b.w, c.w, normal);
    case TriangleRule::lambert_product:
      return product_average(a, b, c) *
             geometry::triangle_projected_solid_angle(a.w, b.w, c.w, normal);
    case TriangleRule::two_kernel:
      return two_kernel_estimate(a, b, c, normal, ctx.emitter_normal, ctx.side, ctx.inv_area);
  }
  return 0.0;
}

}  // namespace luxgrid::nearfield
