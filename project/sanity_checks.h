#pragma once
// Everyday mistakes that are legal input: lengths in millimetres, a spacing larger than the
// surface, a grid too coarse for statistics, flux in kilolumens, rotations in radians, a
// luminaire aimed into a wall close by, a grid that faces out of every room. Each becomes a
// warning in Scene::warnings (the CLI prints it on stderr, results.json lists it) that names the
// object by its JSON pointer and says what luxgrid assumed; the calculation runs as written.
#include "calc/scene.h"
#include "project/json_reader.h"

namespace luxgrid::project {

// A length above this in a room's plan, a plane's size or a spacing reads as millimetres: no
// room or calculation plane of a lighting design is a kilometre long. (A room this high is
// refused by the loader: kMaxRoomHeight_m.)
inline constexpr double kMillimetreSuspect_m = 1000.0;
// Fewer grid points than this per side make Emin, U0 and the maps meaningless.
inline constexpr int kMinGridPointsPerSide = 3;
// A flux_lm below this, on a file whose own flux is at least kKilolumenRatio times larger, reads
// as kilolumens (5.49 meant as 5490 lm): the dimmest real luminaires still emit ~100 lm.
inline constexpr double kKilolumenSuspect_lm = 50.0;
inline constexpr double kKilolumenRatio = 100.0;
// A luminaire whose main beam meets a wall of its room closer than this points into the wall.
inline constexpr double kBeamIntoWall_m = 0.5;
// How far from a surface point the side it faces is probed (inside a room or not), m.
inline constexpr double kFacingProbe_m = 0.01;

// `root` is the project document the scene was parsed from (for the pointers and the values as
// written); the scene is complete (luminaires expanded, grids built).
void add_sanity_warnings(calc::Scene& scene, const JsonValue& root);

// The intensity-weighted mean direction of a distribution in its own frame (unit), or a zero
// vector when its light has no main direction (isotropic, as much up as down).
Vec3 main_beam_direction(const photometry::IntensityDistribution& d);

}  // namespace luxgrid::project
