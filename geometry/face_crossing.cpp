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
  return s;
}

bool segment_crosses(const FaceSheet& face, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double len = glm::length(d);
  if (!(len > 2.0 * kOcclusionEndAllowance_m)) return false;  // the ends touch: nothing between
  const Vec3 step = d * (kOcclusionEndAllowance_m / len);
  const double da = glm::dot(a + step - face.origin, face.normal);
  const double db = glm::dot(b - step - face.origin, face.normal);
  if (!((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0))) return false;
  if (std::max(std::abs(da), std::abs(db)) <= kGrazing_m) return false;  // in plane
  const double t = da / (da - db);
  const Vec3 hit = a + step + t * (d - 2.0 * step) - face.origin;
  const Location where =
      locate(Vec2(glm::dot(hit, face.u), glm::dot(hit, face.v)), face.outline, kGrazing_m);
  return where == Location::inside || (face.solid && where == Location::boundary);
}

}  // namespace luxgrid::geometry
