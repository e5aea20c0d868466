#pragma once
// The integral over an aperture (an opening's triangles seen from a receiver point) of a
// direction-dependent weight times the receiver's cosine, int w(x) cos theta d omega: the sky
// component of a sky of luminance w, through glazing, with obstacles hiding parts of it
// (docs/daylight.md). Each triangle's projected solid angle is exact (Lambert's formula,
// geometry::projected_solid_angle [Baum1989]); what is approximated is w's variation over it: a
// triangle's value is its projected solid angle times the mean of w at three interior nodes
// (barycentric 2/3, 1/6, 1/6), and its error estimate the difference from the sum over its four
// midpoint children. The triangle of largest estimate is refined until the estimates add up to
// the tolerance. A constant w is integrated exactly at the first level (estimate 0).
//
// Three nodes in a large triangle can all miss a narrow peak of w (the sky's brightening around
// the sun, about 20 degrees wide), and then the estimate is small while the error is not: so each
// triangle is first cut until every edge subtends at most `max_edge_angle_rad` from the point
// (the same midpoint children), whatever its estimate.
#include <array>
#include <functional>
#include <vector>

#include "util/robust_math.h"

namespace luxgrid::daylight {

using Triangle3 = std::array<Vec3, 3>;

struct ApertureIntegral {
  double value = 0.0;           // int w cos theta d omega over the triangles
  double error_estimate = 0.0;  // the sum of |coarse - fine| over the final triangles
  int triangles = 0;            // final triangles
  int evaluations = 0;          // calls of w
};

// w(node, unit direction from the point to the node): luminance, transmission and visibility
// along that direction. `triangles` must lie in front of the receiver (clip them first:
// clip_to_receiver below). Refines until error_estimate <= max(absolute_tolerance,
// relative_tolerance x value) or max_triangles are made.
ApertureIntegral integrate_aperture(const std::vector<Triangle3>& triangles, const Vec3& point,
                                    const Vec3& normal,
                                    const std::function<double(const Vec3&, const Vec3&)>& w,
                                    double relative_tolerance, double absolute_tolerance,
                                    int max_triangles, double max_edge_angle_rad = kPi);

// The projected solid angle (sr) of the triangles from `point` for `normal`: the integral of a
// constant 1, exact (the configuration factor times pi).
double aperture_projected_solid_angle(const std::vector<Triangle3>& triangles, const Vec3& point,
                                      const Vec3& normal);

// The parts of `triangles` in front of the receiver (normal . (x - point) >= 0) and on one side
// of the horizontal plane through it (z >= point.z for `above`, else z <= point.z), as
// triangles: each clipped piece is convex and fanned from its first corner.
std::vector<Triangle3> clip_to_receiver(const std::vector<Triangle3>& triangles, const Vec3& point,
                                        const Vec3& normal, bool above);

}  // namespace luxgrid::daylight
