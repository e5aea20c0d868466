#include "calc/glare/ugr.h"

#include <cmath>

#include "calc/glare/guth_position_index.h"
#include "calc/glare/luminous_solid_angle.h"
#include "calc/scene_visibility.h"
#include "photometry/opening.h"
#include "util/error.h"
#include "util/format.h"

namespace luxgrid::calc::glare {

ViewFrame ViewFrame::looking(const Vec3& direction) {
  ViewFrame f;
  f.forward = glm::normalize(direction);
  const Vec3 z(0, 0, 1);
  f.up = glm::normalize(z - glm::dot(z, f.forward) * f.forward);
  f.right = glm::cross(f.forward, f.up);
  return f;
}

std::optional<GlareTerm> glare_term(const photometry::IntensityDistribution& distribution,
                                    const photometry::LuminousOpening& opening, const Pose& pose,
                                    const Vec3& eye, const ViewFrame& view, SolidAngleRule rule) {
  const Vec3 d = pose.position - eye;  // eye -> luminaire
  const double R = glm::dot(d, view.forward), H = glm::dot(d, view.up), T = glm::dot(d, view.right);
  if (!in_guth_field(R, T, H)) return std::nullopt;
  const double dist2 = glm::dot(d, d);
  // Luminaire -> eye in the luminaire frame (the rotation is orthonormal: w * M = M^T w).
  const Vec3 local = (-d / std::sqrt(dist2)) * pose.rotation;
  const double I_cd = distribution.intensity(local);
  const double area_m2 = photometry::projected_area_m2(opening, local);
  if (!(I_cd > 0.0) || !(area_m2 > 0.0)) return std::nullopt;
  GlareTerm t;
  t.L_cd_m2 = I_cd / area_m2;
  t.omega_sr = area_m2 / dist2;
  // Nearer than CIE 117's largest source, A_p / d^2 overstates the solid angle without bound:
  // the exact one (luminous_solid_angle.h), at most 2 pi.
  if (rule == SolidAngleRule::exact_beyond_rated_range && t.omega_sr > kLargestRatedSource_sr) {
    t.omega_sr = luminous_solid_angle_sr(opening, -d * pose.rotation);
    t.exact_solid_angle = true;
  }
  t.p = guth_position_index(H / R, T / R);
  return t;
}

double unified_glare_rating(double sum, double Lb_cd_m2) {
  return 8.0 * std::log10(0.25 * sum / Lb_cd_m2);
}

std::vector<ObserverResult> evaluate_observers(const Scene& scene, const Plan& plan,
                                               const geometry::SurfaceGrid& grid,
                                               const std::vector<double>& E_indirect_lx) {
  std::vector<ObserverResult> out;
  const geometry::Visibility* visibility = plan.visibility_test.get();
  for (size_t i = 0; i < grid.points.size(); ++i) {
    const size_t k = grid.observer[i];
    if (out.size() <= k) out.resize(k + 1);
    out[k].at = grid.points[i];
    ViewResult v;
    v.direction = grid.normals[i];
    v.E_indirect_lx = E_indirect_lx[i];
    v.Lb_cd_m2 = v.E_indirect_lx / kPi;
    const ViewFrame frame = ViewFrame::looking(v.direction);
    double sum = 0.0;
    for (const auto& lum : scene.luminaires) {
      const auto t = glare_term(*lum.distribution, lum.opening, lum.pose, grid.points[i], frame);
      if (!t) continue;
      if (geometry::blocked(visibility, lum.pose.position, grid.points[i])) continue;
      sum += t->value();
      v.terms.push_back({lum.label, *t});
    }
    if (sum > 0.0) {
      if (!(v.Lb_cd_m2 > 0.0)) {
        const std::string view = "observer " + std::to_string(k) + ", view (" +
                                 format_double("%.4g", v.direction.x) + ", " +
                                 format_double("%.4g", v.direction.y) + ", " +
                                 format_double("%.4g", v.direction.z) + ")";
        // Input the user can fix (an eye where no reflected light reaches it): exit 2, the file
        // named by the caller. The loader refuses the usual causes earlier, with the place.
        throw InputError("surface '" + grid.name + "': " + view +
                         ": no reflected light reaches the eye (its indirect illuminance is 0 lx), "
                         "so the background luminance is 0 and UGR is unbounded");
      }
      v.UGR = unified_glare_rating(sum, v.Lb_cd_m2);
      if (!std::isfinite(*v.UGR)) {
        throw CalculationError("surface '" + grid.name + "': observer " + std::to_string(k) +
                               ": UGR is not a finite number; the results are not written");
      }
    }
    out[k].views.push_back(std::move(v));
  }
  return out;
}

std::optional<double> max_ugr(const std::vector<ObserverResult>& observers) {
  std::optional<double> m;
  for (const auto& o : observers)
    for (const auto& v : o.views)
      if (v.UGR && (!m || *v.UGR > *m)) m = v.UGR;
  return m;
}

}  // namespace luxgrid::calc::glare
