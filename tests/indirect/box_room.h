#pragma once
// The closed box room the reflected-light tests build their scenes from.
#include "calc/scene.h"

namespace luxgrid::calc::indirect {

// A w x d x h m box with its corner at the origin, reflectances of floor, walls and ceiling.
inline Room box_room(double w, double d, double h, double rf, double rw, double rc) {
  Room r;
  r.name = "box";
  r.outline = {{0, 0}, {w, 0}, {w, d}, {0, d}};
  r.height = h;
  r.reflectance = {rf, rw, rc};
  return r;
}

}  // namespace luxgrid::calc::indirect
