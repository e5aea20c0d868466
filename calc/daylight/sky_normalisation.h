#pragma once
// A sky's horizontal illuminance per unit zenith luminance, E_h / L_z = the integral of
// L / L_z cos Z over the upper hemisphere, by a converged quadrature: the scale that makes a sky
// give the project's diffuse horizontal illuminance (L_z = E_h / this). The uniform sky's is pi
// and the traditional overcast's 7 pi / 9 in closed form; the general skies have none
// [ISO15469].
#include "calc/daylight/gauss_kronrod.h"
#include "calc/daylight/sky_luminance.h"

namespace luxgrid::daylight {

// The integral in azimuth (outer) and zenith angle (inner), each by adaptive Gauss-Kronrod
// (gauss_kronrod.h) split at the sun's azimuth and zenith angle, where the indicatrix has its
// cusp; the inner integrals to a tenth of the relative tolerance. value in sr; error_estimate
// the outer quadrature's estimate plus the inner ones' (an upper bound in practice).
QuadratureResult horizontal_illuminance_per_zenith_luminance(const SkyModel& sky,
                                                             double relative_tolerance = 1e-10);

}  // namespace luxgrid::daylight
