#include "calc/glare/luminous_solid_angle.h"

#include <cmath>
#include <vector>

#include "geometry/spherical.h"
#include "photometry/opening.h"

namespace luxgrid::calc::glare {

namespace {

// The opening's polygon in the plane z = 0, centred on the origin (convex).
std::vector<Vec3> opening_corners(const photometry::LuminousOpening& opening) {
  return photometry::opening_polygon(opening, kSolidAngleDiskSegments);
}

// Outward horizontal normal of the polygon's edge from a to b (the polygon is centred on the
// origin, so outward is away from it).
Vec3 outward(const Vec3& a, const Vec3& b) {
  Vec3 n(b.y - a.y, a.x - b.x, 0.0);
  return glm::dot(n, a + b) < 0.0 ? -n : n;
}

// Solid angle of the convex planar polygon `corners` seen from `eye`: a fan from corner 0.
double polygon_solid_angle_sr(const std::vector<Vec3>& corners, const Vec3& eye) {
  double sum = 0.0;
  const Vec3 a = corners[0] - eye;
  const double la = glm::length(a);
  for (size_t k = 1; k + 1 < corners.size(); ++k) {
    const Vec3 b = corners[k] - eye, c = corners[k + 1] - eye;
    sum += geometry::triangle_solid_angle(a, la, b, glm::length(b), c, glm::length(c));
  }
  return sum;
}

}  // namespace

double luminous_solid_angle_sr(const photometry::LuminousOpening& opening, const Vec3& eye_local) {
  const std::vector<Vec3> corners = opening_corners(opening);
  if (corners.size() < 3) return 0.0;
  double sum = eye_local.z < 0.0 ? polygon_solid_angle_sr(corners, eye_local) : 0.0;
  if (opening.height > 0.0) {
    const Vec3 up(0.0, 0.0, opening.height);
    for (size_t k = 0; k < corners.size(); ++k) {
      const Vec3 &a = corners[k], &b = corners[(k + 1) % corners.size()];
      if (glm::dot(outward(a, b), eye_local - a) > 0.0)
        sum += polygon_solid_angle_sr({a, b, b + up, a + up}, eye_local);
    }
  }
  return sum;
}

bool inside_luminous_opening(const photometry::LuminousOpening& opening, const Vec3& eye_local) {
  const std::vector<Vec3> corners = opening_corners(opening);
  if (corners.size() < 3) return false;
  constexpr double kOnOpening_m = 1e-9;
  const bool in_height = opening.height > 0.0
                             ? eye_local.z >= -kOnOpening_m && eye_local.z <= opening.height
                             : std::abs(eye_local.z) <= kOnOpening_m;
  if (!in_height) return false;
  for (size_t k = 0; k < corners.size(); ++k) {
    const Vec3 &a = corners[k], &b = corners[(k + 1) % corners.size()];
    if (glm::dot(outward(a, b), eye_local - a) > 0.0) return false;
  }
  return true;
}

}  // namespace luxgrid::calc::glare
