#pragma once
// One sample of the integrand of Luksch et al. 2020 Eq. 3 at a point of the emitter polygon:
// its direction from the receiver, the emitted radiance L_e (Eq. 2) and the geometric term G.
#include <algorithm>
#include <cmath>
#include <limits>

#include "calc/nearfield/receiver_fan.h"
#include "geometry/visibility.h"

namespace luxgrid::nearfield {

// How the models test visibility (geometry/visibility.h; calc/direct passes the scene's AABB
// tree, nullptr means "nothing blocks light" and costs nothing):
//  - far field: one segment, opening centroid -> receiver (hard shadow);
//  - paper cubature, subdivided rungs, adaptive / standard: per quadrature node, the radiance of
//    a node is multiplied by its visibility (0 or 1); the adaptive rung splits first the cells
//    whose nodes disagree, so the shadow edge converges;
//  - reference: per cubature sample.
// Nodes on the opening's boundary are tested from a point moved towards the centroid by
// kVisibilityInsetRelative of the way, so an opening whose edge lies in a wall or floor (a
// luminous wall, a panel flush with a ceiling) is not blocked by that very face: without it the
// segment from an edge node to a receiver on that face runs inside the face's plane.
inline constexpr double kVisibilityInsetRelative = 1e-6;

struct FanSample {
  Vec3 w{0.0};         // unit direction receiver -> emitter point
  double L = 0.0;      // cd/m^2, L_e(-w) = I(-w) / (A cos_e)   (Eq. 2)
  double G = 0.0;      // w . n_x, >= 0 above the horizon      (Eq. 3)
  Vec3 r{0.0};         // emitter point relative to the receiver, m
  double d = 0.0;      // |r|, m
  double I = 0.0;      // cd, I(-w)
  double cos_e = 0.0;  // |s| / d, cosine at the emitter
  double rho = 0.0;    // G / d^3 (1/m^3): the area-form weight cos_r cos_e / d^2 divided by the
                       // plane distance s, which is the same for every point of the polygon
  double vis = 1.0;    // 1 when the node sees the receiver (or no occluder), else 0; I and L
                       // already include it
};

struct SampleContext {
  const Emitter* emitter = nullptr;
  Vec3 normal{0.0};
  double inv_area_distance = 0.0;                  // 1 / (A |s|), 1/m^3
  double plane_distance = 0.0;                     // |s|, m
  Vec3 emitter_normal{0.0};                        // n_A, world
  double side = 1.0;                               // +1 on the emitting side, -1 behind
  double inv_area = 0.0;                           // 1 / A, 1/m^2
  const geometry::Visibility* occluder = nullptr;  // optional, per-node visibility
  Vec3 receiver{0.0};            // the receiver as given (unshifted), world: segment end
  Vec3 shifted_receiver{0.0};    // origin of the relative coordinates `r`, world
  Vec3 origin_to_centroid{0.0};  // emitter centroid relative to shifted_receiver

  // `point` is the receiver as the caller gave it (before the horizon shift): the visibility
  // segments end there.
  SampleContext(const Emitter& e, const ReceiverFan& fan, const geometry::Visibility* occ = nullptr,
                const Vec3& point = Vec3(0.0))
      : emitter(&e),
        normal(fan.normal),
        inv_area_distance(1.0 / (e.area_m2 * fan.plane_distance)),
        plane_distance(fan.plane_distance),
        emitter_normal(e.normal),
        side(fan.front ? 1.0 : -1.0),
        inv_area(1.0 / e.area_m2),
        occluder(occ),
        receiver(point),
        shifted_receiver(fan.receiver),
        origin_to_centroid(e.centroid - fan.receiver) {}

  // Visibility of the emitter point at `r` (relative to the shifted receiver), tested from a
  // point inset towards the centroid by kVisibilityInsetRelative.
  bool node_visible(const Vec3& r) const {
    const Vec3 inset = r + kVisibilityInsetRelative * (origin_to_centroid - r);
    return occluder->visible(shifted_receiver + inset, receiver);
  }

  // `r` is the emitter point relative to the shifted receiver. Every point of the emitter plane
  // is at plane distance |s| from the receiver, so cos_e = |s| / d exactly and
  // L_e = I d / (A |s|) without a division by a small dot product.
  FanSample operator()(const Vec3& r) const {
    FanSample out;
    const double d = glm::length(r);
    out.r = r;
    out.d = d;
    out.w = r / d;
    out.G = std::max(0.0, glm::dot(out.w, normal));
    out.I = emitter->intensity_towards(-out.w);
    out.L = out.I * d * inv_area_distance;
    out.cos_e = plane_distance / d;
    out.rho = out.G / (d * d * d);
    if (occluder && out.I != 0.0 && !node_visible(r)) {
      out.vis = 0.0;
      out.I = 0.0;
      out.L = 0.0;
    }
    return out;
  }
};

// Every public illuminance is finite and >= 0 (docs/nearfield.md, "Conventions"): NaN and negatives
// become 0, +inf becomes the largest double. A model that needs this on a valid input has a bug,
// which the hard-case tests look for with the raw functions.
inline double sanitize_illuminance(double e) {
  if (!(e > 0.0)) return 0.0;
  return std::min(e, std::numeric_limits<double>::max());
}

}  // namespace luxgrid::nearfield
