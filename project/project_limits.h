#pragma once
// What the project loader refuses as too big, too small or too far, before any memory or time is
// spent on it. Each refusal is an InputError naming the limit, the value and the JSON pointer
// (docs/project-format.md, "Limits"). The JSON layer's own limits (file size, nesting) are in
// project/safe_json.h; the intensity limit shared with the photometry readers is in util/limits.h.
#include <cstddef>

#include "calc/indirect/limits.h"
#include "util/limits.h"

namespace luxgrid::project {

// Luminaires in a project, arrays expanded. Each costs time per grid point (below) and, for
// indirect light and near-field models, far more; 20 000 covers a warehouse of 150 x 130
// fittings. 10^5 luminaires ran ~40 minutes.
inline constexpr std::size_t kMaxLuminaires = 20000;
// One side of an `array`: a count beyond it is a typo long before it is a layout.
inline constexpr int kMaxArrayCount = 10000;

// Points of one grid surface: 4 million points is ~200 MB of points, normals and results, far
// beyond any lighting grid (a 100 x 100 m hall at 0.1 m is 1 M points).
inline constexpr double kMaxGridPoints = 4e6;
// Points over all surfaces together: two of the largest grids, ~400 MB.
inline constexpr double kMaxTotalGridPoints = 8e6;
// Luminaire x point pairs: the work of the direct calculation. Measured at draft on two shared
// cores: 35 ns per pair in an empty room, 450 ns with obstacles (visibility rays), so 1e9 pairs
// are ~35 s, or ~8 minutes with obstacles; 20 000 luminaires still get a 50 000-point grid.
inline constexpr double kMaxLuminairePointPairs = 1e9;

// Interreflection bounces when given as a number: the solver's own limit (calc/indirect/limits.h).
inline constexpr int kMaxBounces = calc::indirect::kMaxBounces;

// Rooms in a project and obstacles over all rooms: each is CGAL geometry (straight skeletons,
// exact polygon tests) and visibility faces; 1000 rooms and 10 000 obstacles is a large building.
inline constexpr std::size_t kMaxRooms = 1000;
inline constexpr std::size_t kMaxObstacles = 10000;

// Corners of a room or prism outline: the straight-skeleton inset and the exact simplicity test
// grow faster than linearly with them; a real floor plan has tens.
inline constexpr std::size_t kMaxOutlineCorners = 1000;

// Photometry entries (each reads a file and may integrate its flux, ~10 ms) and calculation
// surface entries (each may inset an outline), and grids after room_surfaces expand (each
// written as up to four files): bounds on the time spent before the calculation starts.
inline constexpr std::size_t kMaxPhotometryEntries = 1000;
inline constexpr std::size_t kMaxSurfaces = 1000;
inline constexpr std::size_t kMaxSurfaceGrids = 10000;

// Characters of a surface name (a room_surfaces grid's name with its " wall 12" included): the
// name becomes file names (`<name>_indirect.png`), which must fit the 255-byte limit of common
// file systems with room for the folder's temporary suffixes.
inline constexpr std::size_t kMaxSurfaceNameLength = 100;

// Sizes of a luminous opening given by `emitter`, m: below 1 mm the near-field models divide by
// a vanishing area (a 1 nm emitter is a point, say "point"); above 1 km it is not a luminaire.
inline constexpr double kMinEmitterSize_m = 1e-3;
inline constexpr double kMaxEmitterSize_m = 1000.0;

// The largest coordinate or length, m (100 km, more than any lit site). A double keeps ~1e-11
// relative precision, so 1e5 m still resolves 1 um, the visibility tolerance; far beyond it the
// geometry tests lose their meaning and products of lengths approach overflow.
inline constexpr double kMaxCoordinate_m = 1e5;

// The highest room, m: the tallest halls (hangars, assembly buildings) are under 200 m, while a
// room in millimetres is 2000 "m" and more. Above it the project is refused with a hint, before
// its grids and patches are sized (an office in millimetres ran out of memory).
inline constexpr double kMaxRoomHeight_m = 1000.0;

// The dimmest peak intensity a multiplier or flux_lm may scale a file to, cd: an indicator LED
// gives about 1e-3 cd. Below, the values reach the subnormal range of a double (1e-308), where
// every product is slow and loses its digits, and the results round to 0 lx.
inline constexpr double kMinScaledIntensity_cd = 1e-6;

// The smallest maintenance factor [EN12464-1]: real plans use 0.5 to 0.9 (0.4 in
// very dirty spaces); a factor below 0.1 would mean losing nine tenths of the light before
// maintenance, a typo (0.08 for 0.8) rather than a plan.
inline constexpr double kMinMaintenanceFactor = 0.1;

// Observers surfaces (glare, calc/glare): observers per surface and viewing directions per
// observer. 360 directions is a 1-degree step around the horizontal, finer than any design
// practice (DIALux uses 15-degree steps); 1000 seated positions cover a large open-plan floor.
inline constexpr std::size_t kMaxObservers = 1000;
inline constexpr std::size_t kMaxViewsPerObserver = 360;
// Corners of an escape route's path (calc/emergency_surfaces.h): a building's longest route has
// tens; the points along it are charged to the grid budget as for any surface.
inline constexpr std::size_t kMaxEscapeRouteCorners = 1000;
// Views x luminaires over all observers surfaces: results.json lists a term per luminaire in
// each view, ~100 bytes each, so 1e6 pairs keep the file near 100 MB at most.
inline constexpr double kMaxViewLuminairePairs = 1e6;
// A view direction needs a horizontal part to define "up" in the view (the Guth position index
// measures heights above the line of sight in the vertical plane through it): directions within
// this sine of the vertical are refused.
inline constexpr double kMinViewHorizontalPart = 1e-3;
// Openings (windows, roof lights: docs/daylight.md) and the corners of each: a facade has tens
// of windows, a polygon a handful of corners; the limits keep the set-up's O(n^2) overlap test
// and each point's integration over openings bounded.
inline constexpr std::size_t kMaxOpenings = 1000;
inline constexpr std::size_t kMaxOpeningCorners = 100;
// Exterior obstructions (daylight.obstructions): every point's view through every opening is
// cut along their edges, so their number multiplies each point's work.
inline constexpr std::size_t kMaxExteriorObstructions = 1000;

}  // namespace luxgrid::project
