#include "calc/indirect/far_kernels.h"

namespace luxgrid::calc::indirect {
namespace {

LUXGRID_LANE void far_form_factors_kernel(const double* ox, const double* oy, const double* oz,
                                          std::size_t count, const Vec3& dc, const Vec3& dn,
                                          const Vec3& sn, double area_m2, double* out) {
  for (std::size_t k = 0; k < count; ++k)
    out[k] = area_m2 * point_kernel_at(dc.x - ox[k], dc.y - oy[k], dc.z - oz[k], sn, dn) / kPi;
}

LUXGRID_LANE void far_terms_kernel(const double* cx, const double* cy, const double* cz,
                                   const double* flux, std::size_t count, const Vec3& x,
                                   const Vec3& n, const Vec3& m, double inner2, double outer2,
                                   double* out) {
  for (std::size_t k = 0; k < count; ++k) {
    const double dx = x.x - cx[k], dy = x.y - cy[k], dz = x.z - cz[k];
    const double d2 = dx * dx + dy * dy + dz * dz;
    const double term = flux[k] * point_kernel_at(dx, dy, dz, m, n);
    out[k] = d2 >= inner2 && d2 < outer2 ? term : 0.0;
  }
}

LUXGRID_LANE double row_dot_kernel(const float* row, const double* v, std::size_t b,
                                   std::size_t e) {
  return simd::dot_in_four_sums(row, v, b, e);
}

}  // namespace

LUXGRID_MULTIVERSION(void, far_form_factors,
                     (const double* ox, const double* oy, const double* oz, std::size_t count,
                      const Vec3& dc, const Vec3& dn, const Vec3& sn, double area_m2, double* out),
                     (ox, oy, oz, count, dc, dn, sn, area_m2, out), far_form_factors_kernel)

LUXGRID_MULTIVERSION(void, far_terms,
                     (const double* cx, const double* cy, const double* cz, const double* flux,
                      std::size_t count, const Vec3& x, const Vec3& n, const Vec3& m, double inner2,
                      double outer2, double* out),
                     (cx, cy, cz, flux, count, x, n, m, inner2, outer2, out), far_terms_kernel)

LUXGRID_MULTIVERSION(double, row_dot,
                     (const float* row, const double* v, std::size_t b, std::size_t e),
                     (row, v, b, e), row_dot_kernel)

}  // namespace luxgrid::calc::indirect
