#pragma once
// What reflected light's solver tells the plan besides its numbers: a patch size it had to raise,
// a luminaire whose light does not enter a room, a room clustered more coarsely than its quality.
// Values with a code (report/plan_text.h words them; results.json keeps them in the plan).
#include <cstddef>
#include <string>
#include <vector>

namespace luxgrid::calc::indirect {

struct IndirectNote {
  enum class Kind {
    // The project's budget of `asked` patches per room is above `limit` (a form-factor matrix of
    // `matrix_mb` MB): `limit` is used.
    budget_above_limit,
    // The patch size raised from `from_m` to `to_m`, estimated before meshing: for `room` to stay
    // within `budget` patches per room, or for all `rooms` rooms to stay within `limit` patches
    // in all rooms (in all clustered rooms when `clustered_limit`).
    room_raised,
    rooms_raised,
    // The same once meshed (obstacles and clipped cells beyond the estimate): for all rooms to
    // stay within `limit` (`clustered_limit` as above), or for `room` within `budget` patches.
    rooms_raised_meshed,
    room_raised_meshed,
    // `luminaire` lies in no room: its light is not reflected.
    luminaire_outside,
    // `fraction` of the luminous opening of `luminaire` (a disk when `disk`, else a rectangle,
    // `length_m` x `width_m`) lies outside its room or inside an obstacle: `entering_lm` of its
    // `flux_lm` enter `rooms_entered`.
    opening_outside,
    // A warning: `room` is clustered with the opening ratio `opening` instead of the quality's
    // `quality_opening`, since the links of `patches` patches at the quality's ratio would exceed
    // `limit_mb` MB; the reflected light near the room's edges may be off by more than the
    // quality's figures.
    clustered_wider,
  };
  Kind kind = Kind::room_raised;
  std::string room, luminaire;
  std::vector<std::string> rooms_entered;
  size_t rooms = 0, budget = 0, limit = 0, asked = 0, matrix_mb = 0, patches = 0, limit_mb = 0;
  bool clustered_limit = false, disk = false;
  double from_m = 0.0, to_m = 0.0;
  double fraction = 0.0, length_m = 0.0, width_m = 0.0, entering_lm = 0.0, flux_lm = 0.0;
  double opening = 0.0, quality_opening = 0.0;
};

}  // namespace luxgrid::calc::indirect
