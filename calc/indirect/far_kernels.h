#pragma once
// The loops of reflected light over many sources at once: the form-factor matrix's far entries
// (radiosity.cpp), the gather's far terms (gather.cpp) and the sweeps' row sums (radiosity.cpp).
// Each is a loop without branches over one formula written once (point_kernel_at,
// simd::dot_in_four_sums), compiled once per target (util/simd.h's LUXGRID_MULTIVERSION: the
// AVX2 version does four divisions at once) with the same bits in each; each version can be
// called by name (tests/indirect/far_kernels_test.cpp calls both).
#include <cstddef>

#include "calc/indirect/form_factor.h"
#include "util/robust_math.h"
#include "util/simd.h"

namespace luxgrid::calc::indirect {

// pi dF/dA (point_kernel_pi_per_m2) between a receiver with normal receiver_normal and a source
// point with normal source_normal, d = (dx, dy, dz) = receiver - source: the heights
// source_normal . d and -receiver_normal . d, no clamp (the callers have checked that both are
// >= 0), d . d, each dot product as glm::dot adds it.
template <class T>
LUXGRID_LANE T point_kernel_at(const T& dx, const T& dy, const T& dz, const Vec3& source_normal,
                               const Vec3& receiver_normal) {
  const T h_source = source_normal.x * dx + source_normal.y * dy + source_normal.z * dz;
  const T h_receiver = -(receiver_normal.x * dx + receiver_normal.y * dy + receiver_normal.z * dz);
  return point_kernel_pi_per_m2(h_source, h_receiver, dx * dx + dy * dy + dz * dz);
}

// The far form factors of sources [0, count) (centroids ox, oy, oz, normal sn) for the receiver
// (centroid dc, normal dn, area): out[k] = area x point_kernel_at / pi, as the caller's tests
// have made sure every term is (all far, in front of each other).
LUXGRID_MULTIVERSION_DECLARE(void, far_form_factors,
                             (const double* ox, const double* oy, const double* oz,
                              std::size_t count, const Vec3& dc, const Vec3& dn, const Vec3& sn,
                              double area_m2, double* out))

// The gather's far kernel of entries [0, count) (centroids cx, cy, cz, fluxes, the group's
// normal m) for the receiver (x, n): out[k] = flux x point_kernel_at where the centroid lies in
// the band d^2 in [inner2, outer2), +0 elsewhere. The caller adds the terms in order, so the sum
// has the bits of adding each as it was made (every term is >= +0: the callers have checked that
// x is in front of every patch and every centroid in front of x, so adding a +0 changes nothing).
LUXGRID_MULTIVERSION_DECLARE(void, far_terms,
                             (const double* cx, const double* cy, const double* cz,
                              const double* flux, std::size_t count, const Vec3& x, const Vec3& n,
                              const Vec3& m, double inner2, double outer2, double* out))

// A form-factor row (floats) times a vector over [b, e): simd::dot_in_four_sums.
LUXGRID_MULTIVERSION_DECLARE(double, row_dot,
                             (const float* row, const double* v, std::size_t b, std::size_t e))

}  // namespace luxgrid::calc::indirect
