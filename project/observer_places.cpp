// Where an observer may stand (project_parts.h, check_observer_places).
#include "calc/glare/luminous_solid_angle.h"
#include "calc/glare/ugr.h"
#include "geometry/polygon.h"
#include "project/project_parts.h"
#include "util/format.h"

namespace luxgrid::project::parts {

using calc::Scene;

namespace {

// The room whose space holds `eye` (its outline, boundary included, between floor and
// ceiling), or none.
const calc::Room* room_around(const Scene& scene, const Vec3& eye) {
  for (const auto& room : scene.rooms) {
    if (eye.z >= room.floor_z && eye.z <= room.floor_z + room.height &&
        geometry::locate(Vec2(eye), room.outline, 0.0) != geometry::Location::outside)
      return &room;
  }
  return nullptr;
}

bool reflects_nothing(const calc::Room& room) {
  if (room.reflectance.floor > 0.0 || room.reflectance.walls > 0.0 ||
      room.reflectance.ceiling > 0.0)
    return false;
  for (const auto& o : room.obstacles)
    if (o.reflectance > 0.0) return false;
  return true;
}

}  // namespace

void check_observer_places(const JsonValue& s, const geometry::SurfaceGrid& grid, Scene& scene) {
  const auto observers = s.at("observers").items();
  size_t first_point = 0;
  for (size_t k = 0; k < observers.size() && first_point < grid.points.size(); ++k) {
    const JsonValue at_v = observers[k].at("at");
    const Vec3 eye = grid.points[first_point];
    size_t end_point = first_point;
    while (end_point < grid.points.size() && grid.observer[end_point] == k) ++end_point;
    for (const auto& room : scene.rooms) {
      for (const auto& o : room.obstacles) {
        if (eye.z > o.z0 && eye.z < o.z1 &&
            geometry::locate(Vec2(eye), o.footprint, 0.0) == geometry::Location::inside) {
          at_v.fail("the observer is inside obstacle \"" + o.name + "\" of room \"" + room.name +
                    "\", where no eye can be");
        }
      }
    }
    // Which luminaires count in any of its views (visibility aside), and the first that is too
    // near for CIE 117's small-source solid angle.
    bool counts = false;
    const calc::Luminaire* nearest = nullptr;
    double nearest_sr = 0.0;
    for (const auto& l : scene.luminaires) {
      const Vec3 local = (eye - l.pose.position) * l.pose.rotation;
      if (calc::glare::inside_luminous_opening(l.opening, local)) {
        at_v.fail("the observer is inside the luminous opening of " + l.label +
                  ", where no glare formula applies");
      }
      for (size_t i = first_point; i < end_point; ++i) {
        const auto t = calc::glare::glare_term(*l.distribution, l.opening, l.pose, eye,
                                               calc::glare::ViewFrame::looking(grid.normals[i]));
        if (!t) continue;
        counts = true;
        if (t->exact_solid_angle && !nearest) nearest = &l, nearest_sr = t->omega_sr;
      }
    }
    if (counts) {
      const calc::Room* room = room_around(scene, eye);
      if (!room) {
        at_v.fail(
            "the observer lies outside every room, where no surface reflects light to the eye: "
            "UGR's background luminance would be 0 and UGR unbounded");
      }
      if (reflects_nothing(*room)) {
        at_v.fail("the observer is in room \"" + room->name +
                  "\", whose surfaces all have reflectance 0: no reflected light reaches the eye, "
                  "so UGR's background luminance would be 0 and UGR unbounded");
      }
    }
    if (!counts && end_point > first_point) {
      // CIE 117's sum has no term: UGR is not defined there (not "no glare"), and the results
      // carry none for its views. Said here, at its place, rather than left as a blank.
      scene.warnings.push_back(
          {at_v.location(), "observer " + std::to_string(k) +
                                ": no luminaire lies in the field of view of any of its views "
                                "(visibility aside), so it has no UGR"});
    }
    if (nearest) {
      scene.warnings.push_back(
          {at_v.location(),
           "observer " + std::to_string(k) + ": " + nearest->label + " subtends " +
               format_double("%.3g", nearest_sr) +
               " sr, more than the 0.1 sr CIE 117 states UGR for; its term takes the exact "
               "solid angle of the luminous area (A_p / d^2 would overstate it), and the UGR "
               "there is outside the formula's range"});
    }
    first_point = end_point;
  }
}

}  // namespace luxgrid::project::parts
