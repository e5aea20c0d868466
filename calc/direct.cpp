#include "calc/direct.h"

#include <atomic>
#include <cmath>
#include <mutex>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace luxgrid::calc {

namespace {
// A receiver closer than this to a point source gets no light from it rather than an infinite
// value: 1 um is far below any grid spacing, and keeps I/d^2 finite.
constexpr double kMinDistanceSquared = 1e-12;  // m^2

// The scene's AABB tree seen through the near-field models' occlusion interface, so area
// emitters cast soft shadows (visibility per quadrature node; calc/nearfield/occluder.h).
class SceneOccluder final : public nearfield::Occluder {
 public:
  explicit SceneOccluder(const Visibility& v) : v_(v) {}
  bool visible(const Vec3& emitter_point, const Vec3& receiver) const override {
    return v_.visible(emitter_point, receiver);
  }

 private:
  const Visibility& v_;
};

// What a point of a grid measures. Horizontal and vertical are planes whose normals the loader
// has set; a half cylinder faces the normal the loader set to its `facing` direction.
nearfield::Receiver receiver_of(geometry::Quantity q, const Vec3& normal) {
  switch (q) {
    case geometry::Quantity::cylindrical: return nearfield::Receiver::cylindrical();
    case geometry::Quantity::semi_cylindrical: return nearfield::Receiver::semi_cylindrical(normal);
    default: return nearfield::Receiver::planar(normal);
  }
}
}  // namespace

double far_field_illuminance(const Luminaire& lum, const Vec3& point, const Vec3& normal) {
  const Vec3 to_point = point - lum.pose.position;
  const double d2 = glm::dot(to_point, to_point);
  if (!(d2 > kMinDistanceSquared)) return 0.0;
  const double d = std::sqrt(d2);
  const Vec3 w = to_point / d;
  const double cos_incidence = -glm::dot(normal, w);
  if (!(cos_incidence > 0.0)) return 0.0;
  // World direction -> luminaire frame: the rotation is orthonormal, so its inverse is its
  // transpose (w * M == transpose(M) * w in glm).
  const Vec3 local = w * lum.pose.rotation;
  const double e = lum.distribution->intensity(local) * cos_incidence / d2;
  return std::isfinite(e) && e > 0.0 ? e : 0.0;
}

std::vector<nearfield::Emitter> make_emitters(const Scene& scene) {
  std::vector<nearfield::Emitter> out;
  out.reserve(scene.luminaires.size());
  for (const auto& l : scene.luminaires) {
    out.push_back(nearfield::make_emitter(l.opening, l.pose.position, l.pose.rotation, l.distribution));
  }
  return out;
}

std::vector<double> direct_illuminance(const Plan& plan,
                                       const std::vector<nearfield::Emitter>& emitters,
                                       const geometry::SurfaceGrid& grid, const Progress& progress,
                                       DirectCounts* counts,
                                       std::vector<double>* estimated_error_lx) {
  std::vector<double> E(grid.points.size(), 0.0);
  if (estimated_error_lx) estimated_error_lx->assign(grid.points.size(), 0.0);
  std::atomic<size_t> done{0};
  std::mutex count_mutex;
  const size_t total = grid.points.size();
  const Visibility* visibility = plan.visibility_test.get();
  // nullptr when nothing can occlude: the near-field models then skip every test.
  std::optional<SceneOccluder> scene_occluder;
  if (visibility) scene_occluder.emplace(*visibility);
  const nearfield::Occluder* occluder = scene_occluder ? &*scene_occluder : nullptr;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, total, 16), [&](const auto& range) {
    DirectCounts local;
    for (size_t i = range.begin(); i != range.end(); ++i) {
      if (!grid.active.empty() && !grid.active[i]) continue;
      double sum = 0.0, error_lx = 0.0;
      const nearfield::Receiver receiver = receiver_of(grid.quantity, grid.normals[i]);
      for (const auto& emitter : emitters) {
        // Soft shadows: the near-field models test visibility per node, the far field from
        // the opening's centre.
        nearfield::SwitchWeights w;
        const double pair = nearfield::hybrid_illuminance(
            emitter, grid.points[i], receiver, plan.near_model, plan.near_switch, occluder, &w);
        sum += pair;
        if (estimated_error_lx) error_lx += pair * nearfield::estimated_pair_error(emitter, w);
        if (!counts) continue;
        if (emitter.is_point()) {
          ++local.point_sources;
        } else {
          (w.far >= 1.0 ? local.far : w.far <= 0.0 ? local.near : local.blended) += 1;
          if (w.far < 1.0 && w.fixed >= 1.0) ++local.fixed_rule;
          if (w.far < 1.0 && w.fixed > 0.0 && w.fixed < 1.0) ++local.fixed_blended;
        }
      }
      E[i] = sum;
      if (estimated_error_lx) (*estimated_error_lx)[i] = error_lx;
    }
    if (counts) {
      std::lock_guard lock(count_mutex);
      *counts += local;
    }
    const size_t now = done += range.size();
    if (progress) progress(static_cast<double>(now) / static_cast<double>(total));
  });
  return E;
}

}  // namespace luxgrid::calc
