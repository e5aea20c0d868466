#pragma once
// The light entering the rooms through their openings (docs/daylight.md): at any point and
// receiver normal, the sky seen through the openings of the point's rooms and the ground below
// the horizon, through the glazing, hidden by what lies inside the rooms, integrated over each
// opening by calc/daylight/aperture_integral. The one copy of that integration: the grid
// points' sky and externally reflected components, the light landing on each patch of the
// reflected light's mesh (its first bounce) and the flux entering through each opening all
// come from here.
#include <vector>

#include "calc/daylight/aperture_integral.h"
#include "calc/daylight/clear_glass.h"
#include "calc/daylight/gauss_kronrod.h"
#include "calc/exterior_obstructions.h"
#include "calc/indirect/patches.h"
#include "calc/indirect/subcells.h"
#include "calc/scene.h"
#include "geometry/visibility.h"

namespace luxgrid::calc {

// The integrals at one point: sky = int (L / L_z) T cos theta d omega over the openings' parts
// above the point's horizontal plane (sr), ground = int T cos theta d omega over the parts below
// (sr), obstruction = int (L_f / E_h) T cos theta d omega over the parts where an exterior
// obstruction's face of luminance L_f is seen instead of the sky or the ground (no unit; 0
// without obstructions), T the glazing, frame and maintenance factors and the visibility; their
// error estimates and the integrand's evaluations.
struct OpeningLightParts {
  double sky = 0.0, ground = 0.0, obstruction = 0.0;
  double sky_error = 0.0, ground_error = 0.0, obstruction_error = 0.0;
  std::size_t evaluations = 0;
};

class DaylightLight {
 public:
  // `visibility` (null: nothing blocks) must outlive this; `relative_tolerance` of each point's
  // value (calc/daylight_run.h, daylight_tolerance).
  DaylightLight(const Scene& scene, const geometry::Visibility* visibility,
                double relative_tolerance);

  OpeningLightParts at(const Vec3& point, const Vec3& normal) const;
  // In percent of E_h: the sky component and the externally reflected component of `parts`.
  double sky_percent(double sky) const { return sky * (100.0 / sky_integral_.value); }
  double ground_percent(double ground) const {
    return ground * (100.0 * ground_reflectance_ / kPi);
  }
  // The externally reflected component ERC (%): the ground's and the obstructions' light, and
  // the same for their error estimates.
  double external_percent(const OpeningLightParts& parts) const {
    return ground_percent(parts.ground) + 100.0 * parts.obstruction;
  }
  double external_error_percent(const OpeningLightParts& parts) const {
    return ground_percent(parts.ground_error) + 100.0 * parts.obstruction_error;
  }
  // The luminance of exterior obstruction k's face (exterior_obstructions.h numbering) over E_h
  // (1 / sr): rho / pi times the illuminance on it from the unobstructed sky and ground over its
  // hemisphere (docs/daylight.md, "Exterior obstructions").
  double face_luminance_per_eh(std::size_t k, int face) const {
    return face_luminance_per_eh_.at(k)[face];
  }
  // Illuminance under the given sky (lx): (SC + ERC) x E_h / 100.
  double illuminance_lx(const OpeningLightParts& parts) const;

  // The flux landing straight from the sky and the ground on each patch of `mesh` (lm): the
  // illuminance integrated over the patch at points kPatchLift_m off it: at its centroid where
  // every opening is more than four of its diameters away, else at the centroids of its four
  // quarters where it has them (patches.h), else of each triangle of its fan, each weighted by
  // its area. Parallel over the patches.
  std::vector<double> patch_flux_lm(const indirect::PatchMesh& mesh) const;
  // The same for the cells of subcells.h (`cells`, cut from patches of `mesh`): the illuminance
  // at kCellSamplesPerSide^2 points of each cut patch, interpolated to its cells' centres
  // (polynomial in each direction, clamped at 0), times the cell's area. The cells only spread
  // their patch's light over it (subcells.h), for which the interpolation is as good as each
  // cell's own integral (docs/daylight.md) at a fraction of the points.
  std::vector<double> cell_flux_lm(const indirect::PatchMesh& mesh,
                                   const indirect::CellMesh& cells) const;

  // The flux entering through opening `k` (lm): its area times the transmitted illuminance on
  // its plane, the same at every point of it (nothing outside the rooms is modelled): the sky
  // and the ground over the opening's outer hemisphere times the glazing's transmittance,
  // integrated by adaptive Gauss-Kronrod in the angle from its normal (inner) and about it
  // (outer, split at the horizon) to 1e-7. The aperture integration (at) cannot give it: seen
  // from just inside, an opening fills a hemisphere. It is independent of the patches' light,
  // which the flux balance compares it with (tests/calc/daylight_irc_test.cpp).
  double entering_flux_lm(std::size_t k) const;
  std::size_t openings() const { return openings_.size(); }

  bool sky_exact() const { return sky_exact_; }
  bool ground_exact() const { return ground_exact_; }
  const daylight::QuadratureResult& sky_integral() const { return sky_integral_; }

  // Points on a patch (or an opening) are taken this far off it into the room: above the
  // occlusion test's end allowance (1 um), so the patch's own face hides nothing.
  static constexpr double kPatchLift_m = 1e-4;

 private:
  struct PreparedOpening {
    std::size_t room = 0;
    std::vector<daylight::Triangle3> triangles;  // the polygon, triangulated in its face
    Vec3 inward_normal{0, 0, 1};
    std::optional<daylight::ClearGlass> glass;
    double factor = 1.0;  // frame x maintenance
    double area_m2 = 0.0;
    Vec3 centre{0.0};  // of its corners, with the radius of a sphere about it holding them
    double radius_m = 0.0;
  };
  // Adds the light through `o` at `point` to `parts`.
  void add_through(const PreparedOpening& o, const Vec3& point, const Vec3& normal,
                   OpeningLightParts& parts) const;
  using Transmitted = std::function<double(const Vec3&, const Vec3&)>;
  // The same where exterior obstructions exist: each part (sky, ground) of the opening cut along
  // the obstructions' edges as seen from the point (daylight/aperture_split.h), each piece
  // integrated as sky, ground or the face it sees.
  void add_obstructed(const PreparedOpening& o, const Vec3& point, const Vec3& normal,
                      const Transmitted& transmitted, OpeningLightParts& parts) const;
  const Scene& scene_;
  const geometry::Visibility* visibility_;
  std::vector<PreparedOpening> openings_;
  daylight::QuadratureResult sky_integral_;
  double relative_tolerance_ = 0.0, ground_reflectance_ = 0.0, diffuse_horizontal_lx_ = 0.0;
  double absolute_floor_of_eh_ = 0.0;  // the integration's absolute tolerance, fraction of E_h
  bool sky_exact_ = false, ground_exact_ = false;
  std::vector<std::array<double, kBoxFaces>> face_luminance_per_eh_;  // per exterior obstruction
  double max_start_edge_rad_ = kPi;  // aperture_integral.h: the sky's start subdivision
};

}  // namespace luxgrid::calc
