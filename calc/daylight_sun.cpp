#include "calc/daylight_sun.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <tbb/parallel_for.h>

#include "calc/daylight_light.h"
#include "calc/exterior_obstructions.h"
#include "calc/opening_placement.h"
#include "calc/scene_visibility.h"
#include "geometry/polygon.h"
#include "geometry/polygon3.h"

namespace luxgrid::calc {

DaylightSun::DaylightSun(const Scene& scene, const geometry::Visibility* visibility)
    : scene_(scene), visibility_(visibility) {
  const DaylightInputs& inputs = *scene.daylight;
  direct_normal_lx_ = inputs.direct_normal_lx.value_or(0.0);
  if (inputs.sun) sun_ = daylight::sun_direction(*inputs.sun, inputs.site.north_angle_deg);
  for (const DaylightOpening& o : scene.openings) {
    SunOpening p;
    p.room = o.room;
    p.inward_normal = o.inward_normal;
    p.cos_outward = -glm::dot(sun_, o.inward_normal);
    double t = o.frame_factor * o.maintenance_factor;
    if (o.glazing_transmittance && p.cos_outward > 0.0)
      t *= daylight::ClearGlass(*o.glazing_transmittance).transmittance(p.cos_outward);
    p.transmitted_normal_lx = direct_normal_lx_ * t;
    // The plane's frame: e1 along the polygon's first edge, e2 = n x e1.
    p.origin = o.polygon.front();
    p.e1 = glm::normalize(o.polygon[1] - o.polygon[0]);
    p.e2 = glm::cross(o.inward_normal, p.e1);
    for (const Vec3& v : o.polygon)
      p.flat.push_back({glm::dot(v - p.origin, p.e1), glm::dot(v - p.origin, p.e2)});
    std::vector<Vec3> corners = o.polygon;
    std::vector<Vec2> ccw = p.flat;
    if (geometry::signed_area(ccw) < 0.0) {
      std::reverse(ccw.begin(), ccw.end());
      std::reverse(corners.begin(), corners.end());
    }
    p.area_m2 = geometry::signed_area(ccw);
    for (const auto& t3 : geometry::triangulate(ccw))
      p.triangles.push_back({corners[t3[0]], corners[t3[1]], corners[t3[2]]});
    openings_.push_back(std::move(p));
  }
}

bool DaylightSun::sun_ray_leaves(const Vec3& crossing) const {
  // The sun ray leaving opening `o` at `crossing` against what lies outside the rooms (exterior
  // obstructions: overhangs, fins, neighbouring buildings), by the same query the sky's
  // integration asks (calc/exterior_obstructions.h).
  return !first_exterior_obstruction(scene_.daylight->obstructions, crossing, sun_);
}

bool DaylightSun::sun_reaches(const SunOpening& o, const Vec3& x) const {
  if (!(o.cos_outward > 0.0)) return false;
  // The crossing of the ray x + t sun_ with the opening's plane; x must lie inside (room side).
  const double height = glm::dot(x - o.origin, o.inward_normal);
  if (!(height > kOpeningPlaneTolerance_m)) return false;
  const Vec3 crossing = x + (height / o.cos_outward) * sun_;
  const Vec2 q{glm::dot(crossing - o.origin, o.e1), glm::dot(crossing - o.origin, o.e2)};
  if (geometry::locate(q, o.flat) == geometry::Location::outside) return false;
  if (geometry::blocked(visibility_, x, crossing)) return false;
  return sun_ray_leaves(crossing);
}

double DaylightSun::at(const Vec3& point, const Vec3& normal) const {
  const double cos_receiver = glm::dot(normal, sun_);
  if (!(cos_receiver > 0.0) || !(direct_normal_lx_ > 0.0)) return 0.0;
  double lx = 0.0;
  for (const SunOpening& o : openings_) {
    if (!inside_room(scene_.rooms[o.room], point)) continue;
    if (sun_reaches(o, point)) lx += o.transmitted_normal_lx * cos_receiver;
  }
  return lx;
}

std::vector<double> DaylightSun::patch_flux_lm(const indirect::PatchMesh& mesh) const {
  std::vector<double> flux(mesh.patches.size(), 0.0);
  if (!(direct_normal_lx_ > 0.0)) return flux;
  tbb::parallel_for(std::size_t{0}, mesh.patches.size(), [&](std::size_t i) {
    const indirect::Patch& p = mesh.patches[i];
    const double cos_patch = glm::dot(p.normal, sun_);
    if (!(cos_patch > 0.0) || p.polygon.size() < 3) return;
    // The patch's plane frame (p.polygon is counter-clockwise about p.normal, so it stays
    // counter-clockwise in (f1, f2)).
    const Vec3 o0 = p.polygon[0];
    const Vec3 f1 = glm::normalize(p.polygon[1] - p.polygon[0]);
    const Vec3 f2 = glm::cross(p.normal, f1);
    const auto flat = [&](const Vec3& v) {
      return Vec2{glm::dot(v - o0, f1), glm::dot(v - o0, f2)};
    };
    geometry::Polygon2 patch2;
    for (const Vec3& v : p.polygon) patch2.push_back(flat(v));
    if (geometry::signed_area(patch2) < 0.0) std::reverse(patch2.begin(), patch2.end());
    const Vec3 lift = p.normal * DaylightLight::kPatchLift_m;
    double sum = 0.0;
    for (const SunOpening& o : openings_) {
      if (o.room != static_cast<std::size_t>(p.room) || !(o.cos_outward > 0.0)) continue;
      for (const auto& tri : o.triangles) {
        // The part of the opening in front of the patch's plane, projected along the sun onto
        // it: the points of the plane that see the sun through that part.
        const geometry::Polygon3 front =
            geometry::clip_to_half_space({tri[0], tri[1], tri[2]}, p.centroid, p.normal);
        if (front.size() < 3) continue;
        geometry::Polygon2 shadow;
        for (const Vec3& v : front)
          shadow.push_back(flat(v - (glm::dot(v - p.centroid, p.normal) / cos_patch) * sun_));
        if (geometry::signed_area(shadow) < 0.0) std::reverse(shadow.begin(), shadow.end());
        if (!(geometry::signed_area(shadow) > 0.0)) continue;
        const geometry::Polygon2 lit = geometry::clip_convex(patch2, shadow);
        if (lit.size() < 3) continue;
        const double lit_m2 = std::abs(geometry::signed_area(lit));
        if (!(lit_m2 > 0.0)) continue;
        double share = 1.0;
        if (visibility_ || !scene_.daylight->obstructions.empty()) {
          // Something inside the room, or an exterior obstruction, may shadow the sunlit part:
          // the share of it the sun reaches, sampled at the centroids of a barycentric
          // subdivision of each fan triangle, weighted by area (the projection above stays exact
          // for the rest).
          constexpr int n = kShadowSamplesPerSide;
          double reached = 0.0, total = 0.0;
          const auto world = [&](const Vec2& u) { return o0 + u.x * f1 + u.y * f2 + lift; };
          for (std::size_t k = 1; k + 1 < lit.size(); ++k) {
            const Vec2 a = lit[0], b = lit[k], c = lit[k + 1];
            const double area =
                0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
            for (int u = 0; u < n; ++u)
              for (int v = 0; v + u < n; ++v) {
                // The upright sub-triangle's centroid, and the inverted one beside it.
                for (int flip = 0; flip < (u + v + 1 < n ? 2 : 1); ++flip) {
                  const double s = (u + (flip ? 2.0 : 1.0) / 3.0) / n;
                  const double t = (v + (flip ? 2.0 : 1.0) / 3.0) / n;
                  const Vec2 q = a + s * (b - a) + t * (c - a);
                  total += area;
                  if (sun_reaches(o, world(q))) reached += area;
                }
              }
          }
          share = total > 0.0 ? reached / total : 0.0;
        }
        sum += lit_m2 * share * o.transmitted_normal_lx * cos_patch;
      }
    }
    flux[i] = sum;
  });
  return flux;
}

double DaylightSun::entering_flux_lm(std::size_t k) const {
  const SunOpening& o = openings_.at(k);
  if (!(o.cos_outward > 0.0)) return 0.0;
  return o.area_m2 * o.cos_outward * o.transmitted_normal_lx;
}

}  // namespace luxgrid::calc
