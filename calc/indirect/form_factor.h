#pragma once
// Form factors of calc/indirect: the exact point-to-polygon (differential area to polygon) form
// factor by Lambert's formula on the horizon-clipped polygon, and the point-to-point kernel used
// far from a patch. Both return the fraction of the light leaving a point, cosine-weighted over
// its hemisphere, that reaches the polygon; equivalently E(x) = M * F for a uniform-exitance
// (Lambertian) polygon of exitance M (lm/m^2) seen from a receiver at x with normal n.
#include <array>

#include "geometry/polygon.h"
#include "geometry/polygon3.h"

namespace luxgrid::calc::indirect {

// Patch-to-patch transfer (the dense matrix, radiosity.cpp, and the clustered links,
// clustered.cpp): a receiver whose plane passes within kEdgeOnDistance_m of a source point sees
// it edge-on (factor 0); patches whose planes are within kCoplanarDistance_m (same normal) are
// coplanar, far below the edge-on distance, so the plane test would give their mutual factors 0
// anyway.
inline constexpr double kEdgeOnDistance_m = 1e-9;
inline constexpr double kCoplanarDistance_m = 1e-11;
// Where visibility counts in patch-to-patch transfer, a source shoots from its centroid this far
// in front of its patch, so that the segments from a wall patch do not start on the wall
// (visible_fraction lifts the receiving patch's sample points by as much).
inline constexpr double kShootLift_m = 1e-6;

using geometry::Polygon2;
using geometry::Polygon3;

// Lambert's formula [Baum1989, Eq. 2]: F = (projected solid angle of the polygon seen from x) / pi
//   = (1 / 2 pi) | sum over edges  theta_k  n . (r_k x r_k+1) / |r_k x r_k+1| |,
// with r_k the vertices relative to x and theta_k the angle they subtend, after clipping the
// polygon to the receiver's hemisphere n . (y - x) >= 0 (geometry/polygon3.h, spherical.h).
// Exact for any planar polygon, in [0, 1], bounded however close x is to the polygon (no
// singularity: no spikes near walls or corners).
double point_polygon_form_factor(const Vec3& x, const Vec3& n, const Polygon3& polygon);
// The same for `count` corners at `corners` (no allocation for up to 16 corners).
double point_polygon_form_factor(const Vec3& x, const Vec3& n, const Vec3* corners, int count);

// The point-to-point form-factor kernel of [Gadia2024, Eq. 3] (the differential-area form factor
// cos_s cos_r dA / (pi d^2)) times pi, per unit source area, written with
// the heights instead of the cosines (cos = h / d), for a source point c with normal m and a
// receiver point x with normal n, d2_m2 = |x - c|^2:
//   h_source_m   = m . (x - c): the receiver's height over the source's plane (m),
//   h_receiver_m = n . (c - x): the source's height over the receiver's plane (m),
//   result       = h_source_m h_receiver_m / d^4 = pi dF/dA  (1/m^2).
// Symmetric in the two heights; both must be >= 0 (the callers test it: behind either plane the
// term is 0). The one copy of this formula: the gather, the form-factor matrix and the quarter
// rule call it, and multiply by the area and divide by pi themselves (once per sum).
// Over one value or lanes (T; far_kernels.h's loops).
template <class T>
inline T point_kernel_pi_per_m2(const T& h_source_m, const T& h_receiver_m, const T& d2_m2) {
  return h_source_m * h_receiver_m / (d2_m2 * d2_m2);
}

// The point-to-point kernel of [Gadia2024, Eq. 3], as a form factor: a patch of area A at centroid
// c with normal m, seen from x with normal n:
//   F = A max(0, m . (x - c)) max(0, n . (c - x)) / (pi |x - c|^4).
// Relative error against the exact value is about (D / d)^2 / (2 pi) for a patch of diameter D
// at distance d (on-axis disk: exact a^2/(a^2+d^2) vs a^2/d^2); 0.6 % at d = 5 D.
double point_kernel_form_factor(const Vec3& x, const Vec3& n, const Vec3& c, const Vec3& m,
                                double area_m2);

// The form factor of a parallelogram patch (polygon, centroid, area, diameter) at an intermediate
// distance,
// without Lambert's atan2s: the point kernel on the patch (F1, the one-point midpoint rule of the
// form-factor integral) and on its four quarters (F4, the 2 x 2 midpoint rule, centroids
// `quarter`), extrapolated (Richardson): the midpoint rules' leading errors go as the square of
// the cell size, so (4 F4 - F1) / 3 removes it and leaves an error of order (D / d)^4, below the
// plain kernel's (D / d)^2 / (2 pi) at the far switch. Returns -1 (the caller then uses the exact
// formula) when a quarter's centroid is not farther than sqrt(min_d2) from x, when any vertex is
// not in front of the receiver's tangent plane (the horizon clip is the exact formula's job),
// or when the extrapolation comes out negative.
double quarter_kernel_form_factor(const Vec3& x, const Vec3& n, const Polygon3& polygon,
                                  const Vec3& centroid, const std::array<Vec3, 4>& quarter,
                                  const Vec3& m, double area_m2, double diameter_m, double min_d2);

}  // namespace luxgrid::calc::indirect
