#include "geometry/occlusion.h"

#include <embree3/rtcore.h>

#include <array>
#include <limits>
#include <stdexcept>

#include "geometry/face_crossing.h"
#include "geometry/shaft.h"

namespace luxgrid::geometry {

namespace {

// Embree tests in float about the scene's centre: its errors are a few float ulps of the scene's
// half-size. Triangles are grown and rays lengthened by this much, so that every face the segment
// crosses by geometry/face_crossing.h's rule is among Embree's candidates; that rule, in double,
// then decides each candidate (filter_candidate). 1e-5 of the size is about 170 ulps.
double candidate_margin_m(double half_size_m) {
  return kOcclusionEndAllowance_m + 1e-5 * half_size_m;
}

// `t` scaled about its incentre so that each edge moves out by `margin_m`.
std::array<Vec3, 3> grown(const std::array<Vec3, 3>& t, double margin_m) {
  const double la = glm::length(t[1] - t[2]), lb = glm::length(t[2] - t[0]),
               lc = glm::length(t[0] - t[1]);
  const double perimeter = la + lb + lc;
  const double area = 0.5 * glm::length(glm::cross(t[1] - t[0], t[2] - t[0]));
  const Vec3 incentre = (la * t[0] + lb * t[1] + lc * t[2]) / perimeter;
  const double inradius = 2.0 * area / perimeter;
  const double scale = (inradius + margin_m) / inradius;
  return {incentre + scale * (t[0] - incentre), incentre + scale * (t[1] - incentre),
          incentre + scale * (t[2] - incentre)};
}

// The query's segments, for the filter: from `a` to each of `b`, the ray's id its index.
struct SegmentContext {
  RTCIntersectContext context;  // first: Embree passes a pointer to it back to the filter
  Vec3 a;
  const Vec3* b;
  const std::vector<FaceSheet>* sheets;
  const std::vector<unsigned>* face_of;
};

void filter_candidate(const RTCFilterFunctionNArguments* args) {
  const auto* q = reinterpret_cast<const SegmentContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
    const unsigned id = RTCRayN_id(args->ray, args->N, i);
    const FaceSheet& face = (*q->sheets)[(*q->face_of)[prim]];
    if (!segment_crosses(face, q->a, q->b[id])) args->valid[i] = 0;
  }
}

// The candidates' ray for the segment from `a` to `b` (length `len` > 0): from `margin_m` before
// `a` to `margin_m` after `b`, relative to the scene's centre, in float.
RTCRay candidate_ray(const Vec3& a, const Vec3& b, double len, double margin_m, const Vec3& centre,
                     unsigned id) {
  const Vec3 dir = (b - a) / len;
  const Vec3 o = a - margin_m * dir - centre;
  RTCRay ray;
  ray.org_x = static_cast<float>(o.x), ray.org_y = static_cast<float>(o.y);
  ray.org_z = static_cast<float>(o.z);
  ray.dir_x = static_cast<float>(dir.x), ray.dir_y = static_cast<float>(dir.y);
  ray.dir_z = static_cast<float>(dir.z);
  ray.tnear = 0.0f;
  ray.tfar = static_cast<float>(len + 2.0 * margin_m);
  ray.time = 0.0f, ray.mask = 0xFFFFFFFFu, ray.id = id, ray.flags = 0;
  return ray;
}

}  // namespace

struct OcclusionTree::Impl {
  explicit Impl(const std::vector<Face>& faces) : shafts(faces) {}
  ShaftClassifier shafts;
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  Vec3 centre{0.0};  // vertices are stored relative to it
  double margin_m = 0.0;
  std::vector<FaceSheet> sheets;
  std::vector<unsigned> face_of;  // per triangle, its face in `sheets`
  // Per face, whether the trace has a triangle of it (a face whose triangles are all degenerate
  // is never a candidate, so it never blocks).
  std::vector<bool> traced;
};

OcclusionTree::OcclusionTree(const std::vector<Face>& faces)
    : impl_(std::make_unique<Impl>(faces)) {
  std::vector<std::array<Vec3, 3>> tris;
  for (const auto& f : faces) {
    for (const auto& t : triangulate_face(f)) {
      if (!(glm::length(glm::cross(t[1] - t[0], t[2] - t[0])) > 0.0)) continue;  // degenerate
      tris.push_back(t);
      impl_->face_of.push_back(static_cast<unsigned>(impl_->sheets.size()));
    }
    impl_->traced.push_back(impl_->face_of.size() > 0 &&
                            impl_->face_of.back() == impl_->sheets.size());
    impl_->sheets.push_back(face_sheet(f));
  }
  if (tris.empty()) return;
  Vec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const auto& t : tris)
    for (const auto& p : t) lo = glm::min(lo, p), hi = glm::max(hi, p);
  impl_->centre = 0.5 * (lo + hi);
  impl_->margin_m = candidate_margin_m(0.5 * glm::length(hi - lo));
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device) throw std::runtime_error("embree: cannot create a device");
  impl_->scene = rtcNewScene(impl_->device);
  rtcSetSceneFlags(impl_->scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_HIGH);
  RTCGeometry g = rtcNewGeometry(impl_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * tris.size()));
  auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), tris.size()));
  for (size_t i = 0; i < tris.size(); ++i) {
    const auto big = grown(tris[i], impl_->margin_m);
    for (size_t k = 0; k < 3; ++k) {
      const Vec3 p = big[k] - impl_->centre;
      for (int c = 0; c < 3; ++c) v[9 * i + 3 * k + c] = static_cast<float>(p[c]);
      idx[3 * i + k] = static_cast<unsigned>(3 * i + k);
    }
  }
  rtcSetGeometryOccludedFilterFunction(g, filter_candidate);
  rtcCommitGeometry(g);
  rtcAttachGeometry(impl_->scene, g);
  rtcReleaseGeometry(g);
  rtcCommitScene(impl_->scene);
}

OcclusionTree::~OcclusionTree() {
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

bool OcclusionTree::visible(const Vec3& a, const Vec3& b) const {
  if (!impl_->scene) return true;
  const double len = glm::length(b - a);
  if (!(len > 2.0 * kOcclusionEndAllowance_m)) return true;  // the ends touch: nothing between
  SegmentContext q;
  rtcInitIntersectContext(&q.context);
  q.a = a, q.b = &b, q.sheets = &impl_->sheets, q.face_of = &impl_->face_of;
  RTCRay ray = candidate_ray(a, b, len, impl_->margin_m, impl_->centre, 0);
  rtcOccluded1(impl_->scene, &q.context, &ray);
  return ray.tfar >= 0.0f;  // Embree sets tfar to -inf on an accepted hit
}

void OcclusionTree::visible_from(const Vec3& a, std::span<const Vec3> b, bool* seen) const {
  if (!impl_->scene || b.size() > kMaxSegmentsFrom) {
    Visibility::visible_from(a, b, seen);
    return;
  }
  SegmentContext q;
  rtcInitIntersectContext(&q.context);
  q.context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  q.a = a, q.b = b.data(), q.sheets = &impl_->sheets, q.face_of = &impl_->face_of;
  std::array<RTCRay, kMaxSegmentsFrom> rays;
  std::array<unsigned, kMaxSegmentsFrom> index;
  unsigned m = 0;
  for (size_t i = 0; i < b.size(); ++i) {
    const double len = glm::length(b[i] - a);
    seen[i] = true;  // the ends touch: nothing between
    if (!(len > 2.0 * kOcclusionEndAllowance_m)) continue;
    index[m] = static_cast<unsigned>(i);
    rays[m++] =
        candidate_ray(a, b[i], len, impl_->margin_m, impl_->centre, static_cast<unsigned>(i));
  }
  if (m == 0) return;
  rtcOccluded1M(impl_->scene, &q.context, rays.data(), m, sizeof(RTCRay));
  for (unsigned k = 0; k < m; ++k) seen[index[k]] = rays[k].tfar >= 0.0f;
}

Shaft OcclusionTree::classify(std::span<const Vec3> a, std::span<const Vec3> b) const {
  return impl_->scene ? impl_->shafts.classify(a, b) : Shaft::visible;
}

Shaft OcclusionTree::classify_within(std::span<const Vec3> a, std::span<const Vec3> b,
                                     const ShaftFaces& among, ShaftFaces& undecided) const {
  if (!impl_->scene) {
    undecided = ShaftFaces{};
    return Shaft::visible;
  }
  return impl_->shafts.classify(a, b, among, undecided);
}

bool OcclusionTree::visible_among(const Vec3& from, const Vec3& to, const ShaftFaces& faces) const {
  if (!impl_->scene) return true;
  if (!faces.narrowed()) return visible(from, to);
  const ShortenedSegment segment = shortened_segment(from, to);  // once for all the faces
  for (int i = 0; i < faces.count; ++i) {
    const uint32_t face = impl_->shafts.face_of(faces.face[static_cast<size_t>(i)]);
    if (impl_->traced[face] && segment_crosses(impl_->sheets[face], segment)) return false;
  }
  return true;
}

size_t OcclusionTree::triangle_count() const { return impl_->face_of.size(); }

}  // namespace luxgrid::geometry
