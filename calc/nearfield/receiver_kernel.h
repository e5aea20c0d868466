#pragma once
// What a receiver point measures, as a weight on the light arriving from each direction: the one
// copy of the point kernels of planar, cylindrical and semi-cylindrical illuminance. A point
// source of intensity I at distance d seen in the unit direction u (receiver -> source) gives
//   E = I * receiver_weight(receiver, u) / d^2,
// and an area source the integral of (I / A) * receiver_weight(receiver, u) / d^2 over its
// opening (the area form with L dA cos_e = I dA / A, Luksch et al. 2020 Eq. 1-2). The far field
// (far_field.cpp), the table rung (table_cubature.cpp) and the area-form reference
// (area_reference.cpp) all call receiver_weight, so the formulas live here only.
#include <algorithm>
#include <cmath>

#include "util/robust_math.h"

namespace luxgrid::nearfield {

enum class ReceiverKind {
  planar,            // illuminance on a plane with unit normal n: max(0, n . u)
  cylindrical,       // mean vertical illuminance around a vertical axis: sin(eps) / pi
  semi_cylindrical,  // mean over the half cylinder facing f: sin(eps) (1 + cos(alpha)) / pi
};

struct Receiver {
  ReceiverKind kind = ReceiverKind::planar;
  Vec3 direction{0.0, 0.0, 1.0};  // planar: the unit normal; semi-cylindrical: the unit,
                                  // horizontal `facing`; cylindrical: unused

  static Receiver planar(const Vec3& unit_normal) { return {ReceiverKind::planar, unit_normal}; }
  static Receiver cylindrical() { return {ReceiverKind::cylindrical, Vec3(0.0)}; }
  static Receiver semi_cylindrical(const Vec3& unit_horizontal_facing) {
    return {ReceiverKind::semi_cylindrical, unit_horizontal_facing};
  }

  // The normal of the receiver's horizon plane, or the zero vector when the receiver sees the
  // whole sphere: clip_to_horizon (receiver_fan.h) with a zero normal keeps every vertex (every
  // height is 0), so one code path clips a planar receiver and leaves a cylinder's polygon whole.
  // A cylinder (and a half cylinder: its weight is 0 only on the one direction opposite to f) has
  // no horizon.
  Vec3 horizon_normal() const { return kind == ReceiverKind::planar ? direction : Vec3(0.0); }
};

// The weight of the light arriving from unit direction `u` (receiver -> source), >= 0.
//  - planar: the cosine of incidence, 0 behind the plane.
//  - cylindrical (the definition in EN 12464-1 and EN 13201-2; EN 13201-3's point-source
//    formula E_z = I sin(eps) / (pi d^2)): the vertical illuminance on a plane turning about
//    the vertical axis, averaged over the full turn, is (1 / 2 pi) integral of
//    sin(eps) max(0, cos(phi)) d phi = sin(eps) / pi, with sin(eps) = |u_h|, the horizontal
//    part of u.
//  - semi-cylindrical (the definition in EN 13201-2 and EN 12464-1; EN 13201-3's point-source
//    formula E_sc = I sin(eps) (1 + cos(alpha)) / (pi d^2), alpha between the facing direction
//    f and the vertical plane through the source): the same average over the half turn facing
//    f, (1 / pi) integral over |phi| < pi / 2 of sin(eps) max(0, cos(phi - alpha)) d phi =
//    sin(eps) (1 + cos(alpha)) / pi. As |u_h| cos(alpha) = f . u_h it is (|u_h| + f . u) / pi
//    (f horizontal): no division by |u_h|, continuous for light from straight above or below.
//    The max() only removes rounding below 0 (|u_h| + f . u_h >= 0 exactly).
inline double receiver_weight(const Receiver& r, const Vec3& u) {
  switch (r.kind) {
    case ReceiverKind::planar: return std::max(0.0, glm::dot(r.direction, u));
    case ReceiverKind::cylindrical: return std::hypot(u.x, u.y) / kPi;
    case ReceiverKind::semi_cylindrical:
      return std::max(0.0, std::hypot(u.x, u.y) + glm::dot(r.direction, u)) / kPi;
  }
  return 0.0;
}

}  // namespace luxgrid::nearfield
