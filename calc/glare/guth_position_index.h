#pragma once
// The Guth position index p of CIE 117's UGR formula: how much less a glare source annoys at its
// place in the field of view than on the line of sight (p = 1 there, larger away from it).
//
// Closed form [Levin1975], fitted to the Luckiesh-Guth table that CIE 117 reprints (its Table 4.1,
// [CIE117]) and used by Radiance's glare tools (Radiance, src/util/glarendx.c):
//   p = exp[(35.2 - 0.31889 tau - 1.22 e^(-2 tau / 9)) 1e-3 sigma
//           + (21 + 0.26667 tau - 0.002963 tau^2) 1e-5 sigma^2]
// sigma: the angle between the line of sight and the direction to the source, degrees;
// tau: the angle, at the line of sight, between the upward vertical and the plane through the
// line of sight and the source, degrees (0 straight above the line of sight, 90 level with it).
// In the table's coordinates, for a source R ahead along the line of sight, T to the side and H
// above it: tan(sigma) = sqrt(H^2 + T^2) / R, tan(tau) = T / H.
//
// Range: the table covers H/R from 0 to 1.9 and T/R from 0 to 3 (sources above the line of
// sight); in_guth_field says whether a source lies there, and only such sources count in a UGR
// sum (docs/glare.md). Over that range the fit stays within about 10 % of the table
// (tests/calc/guth_position_index_test.cpp).

namespace luxgrid::calc::glare {

// The table's extent, as ratios to the distance R along the line of sight.
inline constexpr double kGuthMaxHOverR = 1.9;
inline constexpr double kGuthMaxTOverR = 3.0;

// True for a source ahead of the eye (R > 0), not below the line of sight (H >= 0: a source
// centred exactly on it counts, as the table's H/R = 0 row does) and within the table's extent
// (H/R <= 1.9, |T|/R <= 3, both inclusive).
bool in_guth_field(double R_m, double T_m, double H_m);

// p for a source at H/R >= 0 and T/R (sign ignored); finite and >= 1 for every finite input.
double guth_position_index(double H_over_R, double T_over_R);

}  // namespace luxgrid::calc::glare
