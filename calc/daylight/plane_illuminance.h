#pragma once
// The illuminance on a plane from the whole unobstructed sky and ground over its hemisphere
// (docs/daylight.md): the light an opening lets in per unit area (through its glazing), and the
// light falling on an exterior obstruction's face, whose luminance follows from it.
#include <functional>

#include "calc/daylight/sky_luminance.h"

namespace luxgrid::daylight {

// int L(d) w(cos theta) cos theta d omega over the hemisphere about `outward_normal` (lx), L the
// sky's luminance `sky_lx_per_relative` x relative_luminance above the horizon and `ground_lx`
// below it (CIE 171's uniform ground), w a weight of the angle of incidence (a glazing's
// transmittance; 1 for a bare face). By adaptive Gauss-Kronrod in the angle theta from the
// normal (inner, to 1e-8) and the angle phi about it (outer, to 1e-7, split at phi = pi): phi is
// measured from a horizontal direction in the plane, so the horizon, where the luminance jumps
// from sky to ground, lies at phi = 0 and pi.
double plane_illuminance_lx(const SkyModel& sky, double sky_lx_per_relative, double ground_lx,
                            const Vec3& outward_normal,
                            const std::function<double(double)>& weight);

}  // namespace luxgrid::daylight
