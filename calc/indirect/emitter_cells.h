#pragma once
// The luminous opening of a luminaire as the first bounce sees it: the part of the opening that
// lies inside a room, cut into cells, each a point source at its centre carrying the
// area fraction of the luminaire's intensity (I x cell area / opening area, the far field of each
// cell). Light from the part of the opening outside the room (behind its walls, floor or ceiling)
// or inside an obstacle does not enter the room: it has no cell.
//
// Without this the first bounce put the whole flux of a luminaire at its position: a 100 m
// emitter in a 4 m room sent all its lumens into the room while the direct calculation (the near
// field, which spreads them over the opening) let in a few per mille of them.
//
// The opening polygon is the near field's (nearfield::make_emitter: rectangle, or the
// area-preserving N-gon of a disk), so direct and reflected light see the same emitter.
#include <optional>
#include <string>
#include <vector>

#include "calc/indirect/indirect_notes.h"
#include "calc/scene.h"

namespace luxgrid::calc::indirect {

struct EmitterCell {
  Vec3 position{0.0};   // m, world: the cell's area centroid
  double weight = 0.0;  // cell area / opening area: the cell's intensity is weight x I
};

// The cells of one luminaire in one room.
struct RoomCells {
  int room = -1;
  std::vector<EmitterCell> cells;
  double weight = 0.0;  // sum of the cells' weights: the fraction of the flux entering the room
};

// An opening whose diameter is at most this multiple of the room's smallest extent (height,
// outline width or depth) stays one point source at its centroid, as before (a 2 m luminaire in
// a 2.8 m high room: the first bounce only needs each patch's flux, and the point model's error
// on it is measured in tests/indirect, EmitterExtent.*).
inline constexpr double kPointOpeningToRoom = 1.0;
// A larger opening (or one cut by the room's boundary) is split into cells no larger than this
// multiple of the room's smallest extent: 1/4 puts every lit patch at least ~4 cell sizes from
// the cells that light it except near the opening itself, where the point-per-cell error
// ((cell / distance)^2, the five-times rule's bound) is local and conserves the flux.
inline constexpr double kCellToRoom = 0.25;
// At most this many cells along each side of a fan triangle (so at most 4 x 16^2 = 1 024 cells
// per rectangle): keeps the cost bounded for rooms far longer than high.
inline constexpr int kMaxCellsPerSide = 16;

// The parts of the luminaire's opening inside each room of the scene (rooms it does not reach
// are left out). A point opening (or a zero-size one) is one cell of weight 1 in the room
// containing its position. An opening flush with a face (within kOpeningOnFace_m) counts as
// inside the room its emitting side (local -z) faces, only: a downlight in a ceiling that is
// also the floor of the room above lights the room below, once. (Light a distribution sends
// backwards from such an opening is lost, as it was with the point model.)
std::vector<RoomCells> emitter_cells(const Scene& scene, const Luminaire& luminaire);

// An opening flush with a room face (a recessed downlight, whose opening lies in the ceiling
// plane) is inside the room: the clip planes are moved out by this much so that rounding in
// the luminaire's rotation does not cut the opening away.
inline constexpr double kOpeningOnFace_m = 1e-6;

// The plan's note when part of the opening lies outside its rooms (IndirectNote::opening_outside:
// "luminaire 1: 99.84 % of its luminous opening (100 x 100 m) lies outside room 'box' ..."); none
// otherwise.
std::optional<IndirectNote> outside_note(const Luminaire& luminaire,
                                         const std::vector<RoomCells>& parts, const Scene& scene,
                                         double luminous_flux_lm);

}  // namespace luxgrid::calc::indirect
