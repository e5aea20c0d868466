#pragma once
// The baselines of the accuracy study ([Luksch2020, Sec. 4]; docs/accuracy.md): research models
// the near-field ladder is measured against, not models a project can choose. Each is a plain
// function of (emitter, receiver point, receiver unit normal) -> illuminance in lux, finite and
// >= 0, on the same horizon-shifted, horizon-clipped opening as the ladder (calc/nearfield).
#include <cstdint>

#include "calc/nearfield/emitter.h"

namespace luxgrid::study {

// Structured sampling [Luksch2020, Eq. 4]: the corners of the clipped opening and its centre,
// E = Omega / N sum L_e G.
double structured_sampling_illuminance(const nearfield::Emitter& e, const Vec3& point,
                                       const Vec3& normal);

// Most representative point (Drobot 2014 as adapted in [Luksch2020, Sec. 4.2]): L_e at the MRP
// times the exact projected solid angle of the clipped opening.
double mrp_illuminance(const nearfield::Emitter& e, const Vec3& point, const Vec3& normal);

// Monte Carlo with `samples` stratified solid-angle samples (Arvo 1995 spherical-triangle sampling
// over the fan), seeded by `seed`: unbiased, noisy, reproducible.
double monte_carlo_illuminance(const nearfield::Emitter& e, const Vec3& point, const Vec3& normal,
                               int samples, std::uint64_t seed);

}  // namespace luxgrid::study
