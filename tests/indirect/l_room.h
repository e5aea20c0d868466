#pragma once
// The L-shaped room with a cabinet the reflected-light tests of non-convex rooms use.
#include <memory>
#include <string>

#include "calc/scene.h"
#include "geometry/room.h"
#include "photometry/builtin.h"

namespace luxgrid::calc::indirect {

// L-shape, 6 x 4 m less its 3 x 2 m corner, 2.5 m high, with a cabinet beside the reflex corner
// and an isotropic source in the long leg: the short leg is lit round the corner and behind the
// cabinet, where the light changes steeply and a receiver sees some patches whole, some not at
// all and some in part.
inline Scene l_scene(const std::string& name) {
  Room r;
  r.name = "L";
  r.outline = {{0, 0}, {6, 0}, {6, 2}, {3, 2}, {3, 4}, {0, 4}};
  r.height = 2.5;
  r.reflectance = {0.3, 0.6, 0.7};
  r.obstacles.push_back(geometry::make_box("cabinet", {1.6, 1.7, 0.0}, {2.6, 2.1, 1.6}, 0.0, 0.5));
  Luminaire l;
  l.label = "iso";
  l.pose.position = Vec3(4.5, 1.0, 2.3);
  l.distribution = std::make_shared<photometry::IsotropicDistribution>(5000.0 / (4.0 * kPi));
  Scene s;
  s.name = name;
  s.rooms = {r};
  s.luminaires = {l};
  return s;
}

}  // namespace luxgrid::calc::indirect
