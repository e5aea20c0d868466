#pragma once
// The table's part of the far-field error, bounded at every direction (docs/nearfield.md, "What
// the map bounds and what it measures"). The point model E_far = I(w_c) g(c) against the area form
// E_near = (1/A) integral of I(w_x) g(x) dA ([Luksch2020, Eq. 1]; w_x the direction from the
// opening's point x to the receiver, g the receiver's weight cos / r^2) splits, with L the
// intensity's gradient at w_c, into
//   I(w_c) (mean g - g(c))                                  geometry: measured by the map
// + L . (1/A) integral of (w_x - w_c) g(x) dA               first order: |.| <= G kappa delta^2
// + (1/A) integral of (I(w_x) - I(w_c) - L.(w_x - w_c)) g   the table's curvature, kinks, pole
//                                                             and jumps: <= (osc delta + J) mean g
// where delta = asin(rho / d) is the half-angle the opening (circumradius rho about its centroid)
// subtends at distance d: every w_x lies within delta of w_c. G is the largest gradient, osc the
// largest difference of two gradients and J the largest jump of the bilinear table over the
// directions within delta of w_c: read from the table's own cells (corner values), so no
// direction between the map's samples escapes.
#include <vector>

#include "calc/nearfield/far_field_bound.h"

namespace luxgrid::nearfield {

// The share of the promise the table's part may take (the rest for the geometry, which the map
// measures and which falls as (D / d)^2 where the table's kinks fall as D / d).
inline constexpr double kTableShareOfPromise = 0.5;

// Receivers turned at most this far from facing the opening (the map's five normals): the first
// order term's kappa = 2 + 2 (2 + tan 75 degrees) ~ 13.5 (cos / r^2 varies over the opening by at
// most 2 (2 + tan theta) delta of its mean, the chord w_x - w_c is -P x / d to (rho / d)^2), taken
// as 16 for the terms of higher order down to d = 2 D.
inline constexpr double kFirstOrderKappa = 16.0;

// Per map sample (gamma row-major, kCSamples per row, as FarFieldBound::d_far_over_D): the
// distance (x D) beyond which the table's part above is within `budget` (relative to the
// luminaire's value, or to kDimFloor of the table's peak where dimmer) for every direction the
// map interpolates from that sample; 0 where `wanted` is not positive (no pair reads it), and
// kNearEverywhere where no distance is enough (a jump of the table within the cell). Empty when
// the distribution has no bilinear table behind it (analytic profiles, bicubic tables, scaled
// wrappers of type A/B): there the map's measurement alone decides.
std::vector<float> table_far_bound_over_D(const Emitter& e, double budget,
                                          const std::vector<float>& wanted);

}  // namespace luxgrid::nearfield
