#include "calc/nearfield/illuminance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "calc/nearfield/fan_sample.h"
#include "calc/nearfield/far_field_bound.h"
#include "calc/nearfield/fixed_rule.h"
#include "calc/nearfield/models.h"
#include "calc/nearfield/table_rung_scratch.h"
#include "util/format.h"

namespace luxgrid::nearfield {
namespace {

// Default tolerances when Model::tolerance is 0.
constexpr double kDefaultAdaptiveRelTol = 1e-3;
// quality high on an analytic profile: the adaptive rung at this tolerance.
constexpr double kHighAdaptiveRelTol = 1e-3;
// quality reference: each pair's error estimate within 1e-4 of its value, so each point's within
// 1e-4 of its direct light, 30x below the finest promise (high: 0.3 %). Finer tolerances cost
// first order along shadow edges (about 10x the lookups per decade, docs/accuracy.md).
constexpr double kDefaultReferenceRelTol = 1e-4;
// Lookup budget of the reference per point: converges 1e-6 on every protocol point well inside it.
constexpr std::int64_t kReferenceMaxEvaluations = 4'000'000;

}  // namespace

std::string to_string(const Model& m) {
  switch (m.kind) {
    case ModelKind::far_field: return "far field";
    case ModelKind::paper_cubature: return "paper cubature";
    case ModelKind::subdivided: return "paper k=" + std::to_string(m.level);
    case ModelKind::lambert_subdivided: return "lambert k=" + std::to_string(m.level);
    case ModelKind::adaptive:
      return format_double("adaptive %.0e", m.tolerance > 0 ? m.tolerance : kDefaultAdaptiveRelTol);
    case ModelKind::standard: return "standard";
    case ModelKind::high: return "high";
    case ModelKind::reference: return "reference";
  }
  return "?";
}

namespace {

// Hard shadow: the one segment from the opening's centroid (the far field).
bool centroid_visible(const Emitter& e, const Vec3& point, const geometry::Visibility* occ) {
  return !occ || occ->visible(e.centroid, point);
}

// At most this many corners of the opening are tested for a penumbra (a disk's N-gon: every
// (N / kPenumbraCorners)-th corner).
constexpr size_t kPenumbraCorners = 8;
// Openings with more corners than this (a disk's fine polygon) get no pair verdict.
constexpr size_t kMaxVerdictCorners = 64;

// True when the point sees part of the opening but not all of it: the centroid and the corners
// (moved a relative 1e-6 towards the centroid, off the housing's own faces, as the reference
// does) do not all agree. The near/far map bounds the far field and the fixed rule for an
// unoccluded opening only: in a penumbra the far field's one segment and the fixed rule's few
// nodes are off by the hidden fraction (13 % at a floor point beside the inner corner of
// examples/lshape), so the pair takes the near-field rung, which tests visibility per node.
bool in_penumbra(const Emitter& e, const Vec3& point, const geometry::Visibility* occ) {
  if (!occ || e.vertices.empty()) return false;
  const bool centre = occ->visible(e.centroid, point);
  const size_t step = std::max<size_t>(1, e.vertices.size() / kPenumbraCorners);
  for (size_t k = 0; k < e.vertices.size(); k += step) {
    const Vec3& v = e.vertices[k];
    if (occ->visible(v + kVisibilityInsetRelative * (e.centroid - v), point) != centre) return true;
  }
  return false;
}

// The rungs that take the table rung on a table without an occluder.
bool near_model_uses_table(const Model& m) {
  return m.kind == ModelKind::standard || m.kind == ModelKind::high;
}

// The pair's shaft verdict (geometry/shaft.h) for the rungs of `standard` and `high`: `visible`
// when no face can block a segment from the opening (its corners moved a relative 1e-6 towards
// the centroid, as in_penumbra) to the point, `hidden` when every one is blocked. Such a pair is
// the unoccluded pair exactly, or nothing: with `visible` it takes the unoccluded rungs (the table
// rung on a table), where the occluded tier's error indicator steps over the table's kinks
// (tests/rooms/tshape: a ceiling point 0.6 m above a pendant's upward opening, 0.87 % low at
// `standard` against 0.01 % with the table rung, docs/accuracy.md). Costs about as much as a few
// segments, next to a near pair's hundreds of nodes.
geometry::Shaft pair_verdict(const Emitter& e, const Vec3& point, const geometry::Visibility* occ) {
  if (!occ) return geometry::Shaft::visible;
  if (e.vertices.empty() || e.vertices.size() > kMaxVerdictCorners) return geometry::Shaft::partial;
  std::array<Vec3, kMaxVerdictCorners> opening;
  for (size_t k = 0; k < e.vertices.size(); ++k)
    opening[k] = e.vertices[k] + kVisibilityInsetRelative * (e.centroid - e.vertices[k]);
  return occ->classify(std::span<const Vec3>(opening.data(), e.vertices.size()),
                       std::span<const Vec3>(&point, 1));
}

}  // namespace

double illuminance(const Emitter& e, const Vec3& point, const Vec3& normal, const Model& m,
                   const geometry::Visibility* occ, TableRungScratch* scratch) {
  if (!scratch && near_model_uses_table(m)) {
    TableRungScratch own;
    return illuminance(e, point, normal, m, occ, &own);
  }
  // A point opening has no nodes: every model falls back to the far field, so the centroid test.
  if (occ && e.is_point())
    return centroid_visible(e, point, occ) ? far_field_illuminance(e, point, normal) : 0.0;
  switch (m.kind) {
    case ModelKind::far_field:
      return centroid_visible(e, point, occ) ? far_field_illuminance(e, point, normal) : 0.0;
    case ModelKind::paper_cubature: return paper_cubature_illuminance(e, point, normal, occ);
    case ModelKind::subdivided:
      return subdivided_illuminance(e, point, normal, 1 << std::clamp(m.level, 0, 10),
                                    TriangleRule::paper, occ);
    case ModelKind::lambert_subdivided:
      return subdivided_illuminance(e, point, normal, 1 << std::clamp(m.level, 0, 10),
                                    TriangleRule::lambert_product, occ);
    case ModelKind::adaptive:
      return adaptive_illuminance(
          e, point, normal, m.tolerance > 0 ? m.tolerance : kDefaultAdaptiveRelTol, nullptr, occ);
    case ModelKind::standard:
    case ModelKind::high: {
      const geometry::Shaft view = pair_verdict(e, point, occ);
      if (view == geometry::Shaft::hidden) return 0.0;
      const geometry::Visibility* blocking = view == geometry::Shaft::visible ? nullptr : occ;
      if (m.kind == ModelKind::standard)
        return standard_illuminance(e, point, normal, blocking, scratch);
      // A table: the table rung, whose cells are the table's own; the adaptive rung at 1e-3
      // steps over the kinks (worst point 1.6 % off on the study, docs/accuracy.md).
      double lux = 0.0;
      if (!blocking && table_aligned_illuminance(e, point, normal, lux, *scratch)) return lux;
      return adaptive_illuminance(e, point, normal, kHighAdaptiveRelTol, nullptr, blocking);
    }
    case ModelKind::reference:
      return reference_illuminance(e, point, normal,
                                   m.tolerance > 0 ? m.tolerance : kDefaultReferenceRelTol,
                                   kReferenceMaxEvaluations, occ)
          .illuminance_lx;
  }
  return 0.0;
}

double illuminance(const Emitter& e, const Vec3& point, const Receiver& receiver, const Model& m,
                   const geometry::Visibility* occ, TableRungScratch* scratch) {
  if (receiver.kind == ReceiverKind::planar)
    return illuminance(e, point, receiver.direction, m, occ, scratch);
  if (!scratch && near_model_uses_table(m)) {
    TableRungScratch own;
    return illuminance(e, point, receiver, m, occ, &own);
  }
  if (e.is_point() || m.kind == ModelKind::far_field)
    return centroid_visible(e, point, occ) ? far_field_illuminance(e, point, receiver) : 0.0;
  const auto area_form = [&](double rel_tol) {
    return reference_illuminance(e, point, receiver, rel_tol, kReferenceMaxEvaluations, occ)
        .illuminance_lx;
  };
  switch (m.kind) {
    case ModelKind::standard:
    case ModelKind::high: {
      // A measured table: the table rung, cells on the table's kinks, as for planar, and as
      // there for a pair no face can block.
      const geometry::Shaft view = pair_verdict(e, point, occ);
      if (view == geometry::Shaft::hidden) return 0.0;
      double lux = 0.0;
      if ((!occ || view == geometry::Shaft::visible) &&
          table_aligned_illuminance(e, point, receiver, lux, *scratch))
        return lux;
      return area_form(m.kind == ModelKind::standard ? kStandardAreaFormRelTol
                                                     : kHighAdaptiveRelTol);
    }
    case ModelKind::adaptive:
      return area_form(m.tolerance > 0 ? m.tolerance : kDefaultAdaptiveRelTol);
    case ModelKind::reference:
      return area_form(m.tolerance > 0 ? m.tolerance : kDefaultReferenceRelTol);
    default: return area_form(kDefaultAdaptiveRelTol);
  }
}

SwitchWeights switch_weights(const Emitter& e, const Vec3& point) {
  const double size = e.largest_dimension_m;
  if (!(size > 0.0)) return {1.0, 0.0};
  const Vec3 r = point - e.centroid;
  const double d = glm::length(r);
  if (e.far_bound) {
    if (!(d > 0.0)) return {};
    return switch_weights_of_bound(e, e.far_bound->weights(e.world_to_local * (r / d), d), d);
  }
  const double t = (d / size - kBlendStart) / (kBlendEnd - kBlendStart);
  if (t <= 0.0) return {};
  if (t >= 1.0) return {1.0, 0.0};
  return {t * t * (3.0 - 2.0 * t), 0.0};
}

SwitchWeights switch_weights_of_bound(const Emitter& e, const FarFieldBound::Weights& w,
                                      double distance_m) {
  return {w.far, e.rule_nodes.empty() ? 0.0 : w.fixed, w.far_start_m, w.fixed_start_m, distance_m};
}

double estimated_pair_error(const Emitter& e, const SwitchWeights& w) {
  if (!e.far_bound || !(w.distance_m > 0.0)) return 0.0;
  const auto decay = [&](double start_m) { return std::min(1.0, start_m / w.distance_m); };
  double error = 0.0;
  if (w.far > 0.0) error += w.far * e.far_bound->far_error_measured * decay(w.far_start_m);
  if (w.far < 1.0 && w.fixed > 0.0)
    error += (1.0 - w.far) * w.fixed * e.far_bound->fixed_error_measured * decay(w.fixed_start_m);
  return error;
}

bool fixed_rule_may_serve(const Emitter& e, const Receiver& receiver, const Model& near_model,
                          const geometry::Visibility* occ) {
  if (receiver.kind != ReceiverKind::planar) return false;
  return occ || !near_model_uses_table(near_model) ||
         !table_rung_in_closed_form(e, receiver.direction);
}

namespace {

// The pair's illuminance by the models the weights `w` mix.
double mixed_illuminance(const Emitter& e, const Vec3& point, const Receiver& receiver,
                         const Model& near_model, const SwitchWeights& w,
                         const geometry::Visibility* occ, SwitchWeights* used,
                         TableRungScratch* scratch) {
  const Model far = Model::far_field();
  if (used) *used = w;
  if (w.far >= 1.0) return illuminance(e, point, receiver, far, occ);
  double near = 0.0;
  if (w.fixed >= 1.0) {
    near = fixed_rule_illuminance(e, point, receiver, occ);
  } else {
    near = illuminance(e, point, receiver, near_model, occ, scratch);
    if (w.fixed > 0.0)
      near = (1.0 - w.fixed) * near + w.fixed * fixed_rule_illuminance(e, point, receiver, occ);
  }
  if (w.far <= 0.0) return near;
  return (1.0 - w.far) * near + w.far * illuminance(e, point, receiver, far, occ);
}

}  // namespace

double hybrid_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal,
                          const Model& near_model, NearFieldSwitch mode,
                          const geometry::Visibility* occ, TableRungScratch* scratch) {
  return hybrid_illuminance(e, point, Receiver::planar(normal), near_model, mode, occ, nullptr,
                            scratch);
}

double hybrid_illuminance(const Emitter& e, const Vec3& point, const Receiver& receiver,
                          const Model& near_model, NearFieldSwitch mode,
                          const geometry::Visibility* occ, SwitchWeights* used,
                          TableRungScratch* scratch) {
  if (mode == NearFieldSwitch::automatic)
    return hybrid_illuminance_weighted(e, point, receiver, near_model, switch_weights(e, point),
                                       occ, used, scratch);
  SwitchWeights w;
  if (mode == NearFieldSwitch::never) w.far = 1.0;
  return mixed_illuminance(e, point, receiver, near_model, w, occ, used, scratch);
}

double hybrid_illuminance_weighted(const Emitter& e, const Vec3& point, const Receiver& receiver,
                                   const Model& near_model, const SwitchWeights& weights,
                                   const geometry::Visibility* occ, SwitchWeights* used,
                                   TableRungScratch* scratch) {
  SwitchWeights w = weights;
  if (w.fixed > 0.0 && !fixed_rule_may_serve(e, receiver, near_model, occ)) w.fixed = 0.0;
  if ((w.far > 0.0 || w.fixed > 0.0) && !e.is_point() && in_penumbra(e, point, occ))
    w.far = 0.0, w.fixed = 0.0;
  return mixed_illuminance(e, point, receiver, near_model, w, occ, used, scratch);
}

}  // namespace luxgrid::nearfield
