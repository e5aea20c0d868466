#pragma once
// Limits shared by more than one module, so each has exactly one copy.

namespace luxgrid {

// The brightest luminous intensity luxgrid accepts, cd, after every multiplier: a 1e9 cd peak is
// ten times a large searchlight (~1e8 cd), so anything above is a unit or scaling mistake, and it
// keeps E = I / d^2 summed over 20 000 luminaires far from double overflow. The photometry
// readers refuse files above it; the project loader refuses a multiplier or flux_lm that scales
// a distribution above it.
inline constexpr double kMaxIntensity_cd = 1e9;

}  // namespace luxgrid
