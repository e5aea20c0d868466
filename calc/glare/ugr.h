#pragma once
// Discomfort glare at observer positions: the Unified Glare Rating of CIE 117 [CIE117],
//   UGR = 8 log10( (0.25 / Lb) sum L^2 omega / p^2 ),
// per luminaire L = I / A_p (its intensity towards the eye over its luminous area projected on
// that direction, photometry::projected_area_m2), omega = A_p / d^2 (the exact solid angle where
// that exceeds 0.1 sr, luminous_solid_angle.h), p the Guth position index
// (guth_position_index.h), and Lb = E_indirect / pi, the indirect illuminance at the eye on a
// plane facing the view. Only luminaires inside the position index's field (in front, not below
// the line of sight, within the table's extent) and visible from the eye (the plan's visibility
// test, from the opening's centre) count. docs/glare.md has the method and its choices.
#include <optional>
#include <vector>

#include "calc/glare/observer_result.h"
#include "calc/plan.h"
#include "calc/scene.h"
#include "geometry/surface_grid.h"

namespace luxgrid::calc::glare {

// The eye's frame: forward along the line of sight, up the upward vertical made perpendicular
// to it, right = forward x up. `direction` must have a horizontal part (the loader checks).
struct ViewFrame {
  Vec3 forward{1, 0, 0}, up{0, 0, 1}, right{0, -1, 0};
  static ViewFrame looking(const Vec3& direction);
};

// The solid angle a term uses. CIE 117's A_p / d^2 everywhere (what CIE 190's tabular method
// prescribes, so that a table compares with the maker's data sheet), or the exact solid angle of
// the luminous area where A_p / d^2 exceeds the 0.1 sr CIE 117 rates UGR for (an eye at a real
// luminaire: A_p / d^2 grows without bound, a solid angle stays within 2 pi).
enum class SolidAngleRule { cie117_formula, exact_beyond_rated_range };

// The term of one luminaire (distribution and opening at `pose`) for an eye at `eye` looking
// along `view`; none when it lies outside the position index's field, emits nothing towards the
// eye or shows no luminous area. Visibility is the caller's.
std::optional<GlareTerm> glare_term(const photometry::IntensityDistribution& distribution,
                                    const photometry::LuminousOpening& opening, const Pose& pose,
                                    const Vec3& eye, const ViewFrame& view,
                                    SolidAngleRule rule = SolidAngleRule::exact_beyond_rated_range);

// 8 log10(0.25 sum / Lb) for sum > 0 and Lb > 0.
double unified_glare_rating(double sum, double Lb_cd_m2);

// Every observer of an observers surface, each view's UGR with its terms. `E_indirect_lx` is the
// surface's indirect illuminance per point (one point per view, facing it). Throws InputError
// naming the surface, observer and view when a luminaire counts but no reflected light reaches
// the eye (background luminance 0, UGR unbounded).
std::vector<ObserverResult> evaluate_observers(const Scene& scene, const Plan& plan,
                                               const geometry::SurfaceGrid& grid,
                                               const std::vector<double>& E_indirect_lx);

// The largest UGR over all observers and views; none when no view has a luminaire in it.
std::optional<double> max_ugr(const std::vector<ObserverResult>& observers);

}  // namespace luxgrid::calc::glare
