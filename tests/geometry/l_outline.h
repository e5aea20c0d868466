// The L-shaped outline the geometry tests share: a 6 x 6 m square without its 3 x 3 m corner
// (x > 3 and y > 3), counter-clockwise, with its one reflex corner at (3, 3).
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/polygon.h"
#include "geometry/room.h"

namespace luxgrid::geometry::test {

inline const Polygon2 kL = {{0, 0}, {6, 0}, {6, 3}, {3, 3}, {3, 6}, {0, 6}};

// The L, 3 m high, furnished: a turned cabinet, a column up to the ceiling and a thin desk top
// (the visibility tests' scene: faces at every angle, edges for shadows to line up with).
inline std::vector<Face> furnished_l_faces() {
  auto faces = room_faces(RoomShape{"L", kL, 0.0, 3.0, 0.2, 0.5, 0.7});
  for (const auto& o : {make_box("cabinet", {1, 1, 0}, {2, 2, 1.8}, 0.35, 0.4),
                        make_box("column", {4, 1, 0}, {5, 2, 3}, 0.0, 0.5),
                        make_box("desk", {1, 4, 0.7}, {2.5, 5, 0.75}, 0.0, 0.5)}) {
    const auto f = obstacle_faces(o);
    faces.insert(faces.end(), f.begin(), f.end());
  }
  return faces;
}

// A seeded linear congruential generator: uniform doubles in [0, 1), the same on every platform.
struct Lcg {
  uint64_t state = 20250117;
  double operator()() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  }
};

}  // namespace luxgrid::geometry::test
