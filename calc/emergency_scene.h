#pragma once
// The emergency scene of EN 1838 [EN1838]: the project's scene with only the luminaires that
// have an "emergency" entry, each at its emergency output, and no reflected light (EN 1838 counts
// direct light only). Observers surfaces (glare) are left out: UGR is no EN 1838 quantity and
// needs reflected light.
#include "calc/scene.h"

namespace luxgrid::calc {

// Throws InputError when no luminaire has an "emergency" entry (nothing would light the scene).
// Records what it did in the returned scene's `notes`, as values (calc/scene_notes.h).
Scene make_emergency_scene(const Scene& normal);

}  // namespace luxgrid::calc
