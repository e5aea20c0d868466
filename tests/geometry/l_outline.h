// The L-shaped outline the geometry tests share: a 6 x 6 m square without its 3 x 3 m corner
// (x > 3 and y > 3), counter-clockwise, with its one reflex corner at (3, 3).
#pragma once

#include "geometry/polygon.h"

namespace luxgrid::geometry::test {

inline const Polygon2 kL = {{0, 0}, {6, 0}, {6, 3}, {3, 3}, {3, 6}, {0, 6}};

}  // namespace luxgrid::geometry::test
