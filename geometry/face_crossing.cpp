#include "geometry/face_crossing.h"

#include "geometry/occlusion.h"

namespace luxgrid::geometry {

FaceSheet face_sheet(const Face& face) {
  FaceSheet s;
  s.normal = glm::normalize(face.normal);
  s.origin = face.corners.front();
  // u along the first edge that is not degenerate; v completes a right-handed frame in the plane.
  for (size_t i = 1; i < face.corners.size(); ++i) {
    const Vec3 e = face.corners[i] - s.origin;
    const Vec3 in_plane = e - glm::dot(e, s.normal) * s.normal;
    if (glm::length(in_plane) > 0.0) {
      s.u = glm::normalize(in_plane);
      break;
    }
  }
  s.v = glm::cross(s.normal, s.u);
  for (const Vec3& c : face.corners)
    s.outline.emplace_back(glm::dot(c - s.origin, s.u), glm::dot(c - s.origin, s.v));
  s.solid = face.kind == Face::Kind::obstacle;
  const Polygon2& o = s.outline;
  s.outline_lo = s.outline_hi = o.front();
  for (const Vec2& p : o)
    s.outline_lo = glm::min(s.outline_lo, p), s.outline_hi = glm::max(s.outline_hi, p);
  s.rectangle = o.size() == 4;
  for (size_t i = 0; s.rectangle && i < 4; ++i) {
    const Vec2& p = o[i];
    const Vec2& q = o[(i + 1) % 4];
    const bool corner = (p.x == s.outline_lo.x || p.x == s.outline_hi.x) &&
                        (p.y == s.outline_lo.y || p.y == s.outline_hi.y);
    s.rectangle = corner && (p.x == q.x || p.y == q.y);
  }
  return s;
}

ShortenedSegment shortened_segment(const Vec3& a, const Vec3& b) {
  ShortenedSegment s;
  s.a = a, s.b = b, s.d = b - a;
  const double len = glm::length(s.d);
  s.touches = !(len > 2.0 * kOcclusionEndAllowance_m);
  if (!s.touches) s.step = s.d * (kOcclusionEndAllowance_m / len);
  return s;
}

bool segment_crosses(const FaceSheet& face, const Vec3& a, const Vec3& b) {
  return segment_crosses(face, shortened_segment(a, b));
}

bool segment_crosses(const FaceSheet& face, const ShortenedSegment& s) {
  if (s.touches) return false;  // the ends touch: nothing between
  const Vec3 &a = s.a, &b = s.b, &d = s.d, &step = s.step;
  const double da = glm::dot(a + step - face.origin, face.normal);
  const double db = glm::dot(b - step - face.origin, face.normal);
  if (!((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0))) return false;
  if (std::max(std::abs(da), std::abs(db)) <= kGrazing_m) return false;  // in plane
  const double t = da / (da - db);
  const Vec3 hit = a + step + t * (d - 2.0 * step) - face.origin;
  const Vec2 at(glm::dot(hit, face.u), glm::dot(hit, face.v));
  // What locate() would say, without its edge loop, where the hit is well clear of the outline's
  // box: outside it by more than the boundary tolerance, no edge is within kGrazing_m and the
  // ray of its crossing test meets an even number of edges (outside); well inside a rectangle,
  // no edge is within kGrazing_m and one edge lies to its right (inside). kBoxClear_m leaves
  // rounding (1e-13 m at 1 km) far behind.
  constexpr double kBoxClear_m = 2.0 * kGrazing_m;
  if (at.x < face.outline_lo.x - kBoxClear_m || at.x > face.outline_hi.x + kBoxClear_m ||
      at.y < face.outline_lo.y - kBoxClear_m || at.y > face.outline_hi.y + kBoxClear_m)
    return false;
  if (face.rectangle && at.x > face.outline_lo.x + kBoxClear_m &&
      at.x < face.outline_hi.x - kBoxClear_m && at.y > face.outline_lo.y + kBoxClear_m &&
      at.y < face.outline_hi.y - kBoxClear_m)
    return true;
  const Location where = locate(at, face.outline, kGrazing_m);
  return where == Location::inside || (face.solid && where == Location::boundary);
}

}  // namespace luxgrid::geometry
