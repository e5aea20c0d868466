#pragma once
// IES TILT data applied for the luminaire's actual pose: the candela table holds for the
// luminaire as measured (tilt 0); tilted in the scene, its lamp output changes by the file's
// tilt factor (LM-63-2002 Sec. 5.5; HID lamps mostly).
#include <glm/mat3x3.hpp>

#include "calc/scene.h"
#include "photometry/tilt.h"

namespace luxgrid::calc {

// The lamp's tilt in degrees for a luminaire turned by `rotation` (local -> world), read the way
// the file's lamp-to-luminaire geometry says:
//  1 (lamp vertical): the angle between the luminaire's axis (local z) and the vertical;
//  2 (lamp horizontal along C0-C180): the elevation of the local x axis above the horizontal;
//  3 (lamp horizontal along C90-C270): the elevation of the local y axis.
double lamp_tilt_deg(const glm::dmat3& rotation, int lamp_to_luminaire_geometry);

// Multiplies each luminaire's distribution by its file's tilt factor at its actual tilt
// (luminaires whose photometry has no tilt table are left alone). Called once after loading.
void apply_tilt_factors(Scene& scene);

}  // namespace luxgrid::calc
