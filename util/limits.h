#pragma once
// Limits shared by more than one module, so each has exactly one copy.

namespace luxgrid {

// The brightest luminous intensity luxgrid accepts, cd, after every multiplier. The brightest
// luminaires built are searchlights of about 1e9 cd (the 1.5 m carbon-arc and xenon searchlights
// reached 8e8 cd; lighthouse beams stay near 1e7 cd), so a file or project claiming more is a
// typo in a multiplier or unit, or hostile. It also keeps the products formed later (intensity x
// TILT factor x 4 pi, E = I / d^2 summed over 20 000 luminaires) far from overflow. The
// photometry readers refuse files above it; the project loader refuses a multiplier or flux_lm
// that scales a distribution above it.
inline constexpr double kMaxIntensity_cd = 1e9;

}  // namespace luxgrid
