#pragma once
// The table's part of the far-field error, bounded at every direction (docs/nearfield.md, "What
// the map bounds and what it measures"). The point model E_far = I(w_c) g(c) against the area form
// E_near = (1/A) integral of I(w_x) g(x) dA ([Luksch2020, Eq. 1]; w_x the direction from the
// opening's point x to the receiver, g the receiver's weight cos / r^2) splits, with L the
// intensity's gradient at w_c, into
//   I(w_c) (mean g - g(c))                                  geometry: measured by the map
// + L . (1/A) integral of (w_x - w_c) g(x) dA               first order: |.| <= (kappa terms) s1^2
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
// order term is L . (g(c) mean(w_x - w_c) + mean((w_x - w_c)(g(x) - g(c)))). The first mean
// loses its linear part (c is the centroid), leaving the chord's curvature, at most
// 1.5 |x - c|^2 / (d - rho)^2 (kChordKappa); in the second, |w_x - w_c| <= |x - c| / (d - rho)
// and cos / r^2 moves from g(c) by at most (2 + tan 75 degrees) |x - c| / (d - rho) of it (the
// distance 2, the cosine tan theta): at most (G_gamma cos + G_C) 5.73 s1^2 g(c) (kWeightKappa),
// s1^2 = mean |x - c|^2 / (d - rho)^2 (both factors grow with |x - c|), with G_gamma and G_C
// the gradient's parts and cos the foreshortening below. Each taken larger for the terms of
// higher order down to d = 2 D.
inline constexpr double kChordKappa = 2.0;
inline constexpr double kWeightKappa = 8.0;

// A flat opening (its plane normal to the luminaire's axis) seen at gamma from its axis is
// foreshortened along gamma by |cos gamma|: w_x - w_c along the gamma direction is
// cos gamma (x - c) . h / d to second order (h the horizontal of the C plane), so a row line's
// kink and the gamma part of the gradient see cos gamma times the opening's spread. Used where
// the table's grid is the luminaire's frame and the region keeps this far from the poles (there
// the line's normal turns by at most (1 + cot) delta = 2.73 delta over the footprint).
inline constexpr double kForeshortenedPoleDistance = 30.0 * kDegToRad;
// The foreshortened gamma part's own second order: 1.5 |x - c|^2 / (d - rho)^2 times the weight's
// 5.73 |x - c| / (d - rho), at most 8.6 rho / (d - rho) s1^2.
inline constexpr double kThirdOrderKappa = 9.0;

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
