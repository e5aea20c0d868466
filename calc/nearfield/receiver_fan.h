#pragma once
// The receiver-dependent geometry shared by every near-field model (Luksch et al. 2020,
// Sec. 5.2-5.3): the horizon epsilon shift, the emitter polygon clipped by the receiver's
// horizon plane, its closest point CP, and the triangle fan around CP.
#include <array>

#include "calc/nearfield/emitter.h"

namespace luxgrid::nearfield {

// Horizon epsilon shift (Sec. 5.3), relative to the emitter's largest dimension: a receiver
// closer than this to the emitter's plane is moved off the plane to this distance, on its own
// side (the emitting side when exactly in the plane). Why: the radiance substitution
// L_e = I / (A cos) (Eq. 2) is infinite in the plane while the solid angle is zero, so a point in
// the plane evaluates 0 * inf = NaN; and for an intensity that is not zero at gamma = 90 deg
// (isotropic, batwing) the exact illuminance at a point embedded in the emitting plane diverges
// logarithmically, so some regularisation is physics, not only numerics. The authors' demo code
// uses 1 mm for metre units; relative to the emitter it is scale-free (1 mm emitters and 1 km
// emitters behave alike) and 1e-6 of the size changes no value outside the band by more than
// rounding; inside the band the value is held at the band edge, so it is continuous.
// tests/nearfield/hard_cases_test.cpp shows the NaN without it.
inline constexpr double kHorizonShiftRelative = 1e-6;

// Horizon shift for this emitter, m.
inline double horizon_shift_m(const Emitter& e) {
  return kHorizonShiftRelative * e.largest_dimension_m;
}

enum class ClosestPointCase { none, inside, edge, vertex };

// Triangle fan around the closest point. Triangle i = (apex, rim[i], rim[i + 1]), i < triangles.
// Positions are relative to `receiver` (the shifted receiver point), in metres.
struct ReceiverFan {
  Vec3 receiver{0.0};           // shifted receiver point, world
  Vec3 normal{0.0, 0.0, 1.0};   // receiver normal, unit
  double plane_distance = 0.0;  // |signed distance| of `receiver` to the emitter plane, > 0
  bool front = true;            // receiver on the emitting side
  ClosestPointCase cp_case = ClosestPointCase::none;
  int triangles = 0;
  Vec3 apex{0.0};
  std::array<Vec3, kMaxPolygonVertices + 1> rim;
};

// Clips the emitter polygon by the horizon plane {p : (p - point) . normal >= 0}, in
// coordinates relative to `point` (geometry::clip_to_half_space_relative). Fewer than three
// vertices means nothing is visible.
OpeningPolygon clip_to_horizon(const Emitter& e, const Vec3& point, const Vec3& normal);

// The receiver moved off the emitter's plane by the horizon shift when closer than `shift_m`
// (0 disables it), on its own side (the emitting side when exactly in the plane).
struct ShiftedReceiver {
  Vec3 point{0.0};              // world
  double plane_distance = 0.0;  // |signed distance| to the emitter plane after the shift
  bool front = true;            // on the emitting side
};
ShiftedReceiver shift_off_emitter_plane(const Emitter& e, const Vec3& point, double shift_m);

// Applies the horizon shift `shift_m` (0 disables it), clips, finds CP and builds the fan.
// `normal` must be a unit vector. Returns triangles == 0 when no part of the emitter is above
// the horizon.
ReceiverFan build_fan(const Emitter& e, const Vec3& point, const Vec3& normal, double shift_m);

}  // namespace luxgrid::nearfield
