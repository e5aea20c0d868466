#pragma once
// Optional occlusion for the near-field models (soft shadows of area emitters, docs/geometry.md).
// calc/nearfield knows nothing of scenes or CGAL: calc/direct adapts its Visibility (an AABB tree)
// to this interface. Every model takes `const Occluder*`; nullptr means "nothing blocks light"
// and costs nothing.
#include "util/robust_math.h"

namespace luxgrid::nearfield {

class Occluder {
 public:
  virtual ~Occluder() = default;
  // True when light travels freely from `emitter_point` (a point of the opening, world, m) to
  // `receiver` (world, m). Called from worker threads: implementations must be thread-safe.
  virtual bool visible(const Vec3& emitter_point, const Vec3& receiver) const = 0;
};

// How the models use it:
//  - far field and the study baselines: one segment, opening centroid -> receiver (hard shadow);
//  - paper cubature, subdivided rungs, adaptive / standard: per quadrature node, the radiance of
//    a node is multiplied by its visibility (0 or 1); the adaptive rung splits first the cells
//    whose nodes disagree, so the shadow edge converges;
//  - reference: per cubature sample.
// Nodes on the opening's boundary are tested from a point moved towards the centroid by
// kOccluderInsetRelative of the way, so an opening whose edge lies in a wall or floor (a
// luminous wall, a panel flush with a ceiling) is not blocked by that very face: without it the
// segment from an edge node to a receiver on that face runs inside the face's plane.
inline constexpr double kOccluderInsetRelative = 1e-6;

}  // namespace luxgrid::nearfield
