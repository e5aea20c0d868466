#pragma once
// Direct sunlight through the openings (docs/daylight.md, "Direct sunlight"): the sun as a point
// direction of direct normal illuminance E_n (daylight.sun.direct_normal_lx), seen from a point
// through an opening when the ray from the point towards the sun crosses the opening's polygon,
// nothing inside the room hides the crossing and the receiver faces the sun. Its illuminance is
// E_n cos(incidence on the receiver) x frame x maintenance x the glazing's transmittance at the
// sun's incidence on the pane. No part of the daylight factor: the daylight scene adds it to E
// in lux beside it (calc/daylight_run.cpp). The one copy of the sun's light: the grid points'
// direct sun, the sunlit flux on each patch of the reflected light's mesh (its first bounce) and
// the flux entering through each opening all come from here.
#include <array>
#include <vector>

#include "calc/daylight/clear_glass.h"
#include "calc/indirect/patches.h"
#include "calc/scene.h"
#include "geometry/visibility.h"

namespace luxgrid::calc {

class DaylightSun {
 public:
  // The scene's daylight must ask for direct sun (DaylightInputs::direct_normal_lx) with the sun
  // above the horizon. `visibility` (null: nothing blocks) must outlive this.
  DaylightSun(const Scene& scene, const geometry::Visibility* visibility);

  // The direct sun's illuminance at `point` on a receiver of unit `normal` (lx).
  double at(const Vec3& point, const Vec3& normal) const;

  // The direct sun's flux landing on each patch of `mesh` (lm): the opening projected along the
  // sun onto the patch's plane and clipped by the patch (the exact sunlit area when nothing
  // inside the room shadows it); where something may (an occlusion test is set), the sunlit
  // part's share the sun reaches is sampled at kShadowSamples points of it. Parallel over the
  // patches.
  std::vector<double> patch_flux_lm(const indirect::PatchMesh& mesh) const;

  // The direct sun's flux entering through opening `k` (lm): E_n x its area x cos(the sun's
  // angle to its outward normal) x the glazing's transmittance there x its factors.
  double entering_flux_lm(std::size_t k) const;
  std::size_t openings() const { return openings_.size(); }

  const Vec3& direction() const { return sun_; }  // towards the sun, unit
  double direct_normal_lx() const { return direct_normal_lx_; }

  // Each sunlit fan triangle of a patch is tested for shadows at this many points (a 4 x 4
  // barycentric subdivision's centroids) when an occlusion test is set.
  static constexpr int kShadowSamplesPerSide = 4;

 private:
  struct SunOpening {
    std::size_t room = 0;
    std::vector<std::array<Vec3, 3>> triangles;  // the polygon, triangulated in its face
    std::vector<Vec2> flat;                      // the polygon in (origin, e1, e2)
    Vec3 origin{0.0}, e1{1, 0, 0}, e2{0, 1, 0};  // its plane's frame
    Vec3 inward_normal{0, 0, -1};
    double area_m2 = 0.0;
    // cos of the sun's angle to the outward normal: the sun enters only where it is > 0.
    double cos_outward = 0.0;
    // E_n x frame x maintenance x the glazing's transmittance at the sun's incidence (lx on a
    // plane facing the sun).
    double transmitted_normal_lx = 0.0;
  };
  // Whether the sun ray leaving an opening at `crossing` (on its polygon) reaches the sky: no
  // exterior obstruction hides it.
  bool sun_ray_leaves(const Vec3& crossing) const;
  // The sun at `x` through `o` is hidden neither inside the room nor outside it.
  bool sun_reaches(const SunOpening& o, const Vec3& x) const;

  const Scene& scene_;
  const geometry::Visibility* visibility_;
  Vec3 sun_{0, 0, 1};
  double direct_normal_lx_ = 0.0;
  std::vector<SunOpening> openings_;
};

}  // namespace luxgrid::calc
