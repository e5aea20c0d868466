// The cubature as published [Luksch2020, Sec. 5.2, Eq. 10], on the fan of receiver_fan.
#include "calc/nearfield/fan_sample.h"
#include "calc/nearfield/models.h"
#include "calc/nearfield/triangle_rule.h"

namespace luxgrid::nearfield {

double paper_cubature_raw(const Emitter& e, const Vec3& point, const Vec3& normal, double shift_m,
                          const geometry::Visibility* occluder) {
  if (e.is_point()) return far_field_illuminance(e, point, normal);
  const ReceiverFan fan = build_fan(e, point, normal, shift_m);
  if (fan.triangles == 0) return 0.0;
  const SampleContext sample(e, fan, occluder, point);
  const FanSample apex = sample(fan.apex);
  // The inside case's rim is closed (rim[m] == rim[0]); sample each point once.
  const bool closed = fan.cp_case == ClosestPointCase::inside;
  FanSample first = sample(fan.rim[0]);
  FanSample prev = first;
  double sum = 0.0;
  for (int i = 0; i < fan.triangles; ++i) {
    const FanSample next = (closed && i + 1 == fan.triangles) ? first : sample(fan.rim[i + 1]);
    sum += paper_triangle(apex, prev, next);  // [Luksch2020, Eq. 10]
    prev = next;
  }
  return sum;
}

double paper_cubature_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal,
                                  const geometry::Visibility* occluder) {
  return sanitize_illuminance(paper_cubature_raw(e, point, normal, horizon_shift_m(e), occluder));
}

}  // namespace luxgrid::nearfield
