#pragma once
// What an observers surface produced (calc/glare/ugr.h computes it; report/ writes it).
#include <optional>
#include <string>
#include <vector>

#include "util/robust_math.h"

namespace luxgrid::calc::glare {

// One luminaire's part of a UGR sum: its luminance towards the eye, the solid angle of its
// projected luminous area and its Guth position index; it adds L^2 omega / p^2.
struct GlareTerm {
  double L_cd_m2 = 0.0;
  double omega_sr = 0.0;
  double p = 1.0;
  bool exact_solid_angle = false;  // omega is the exact solid angle (A_p / d^2 exceeded 0.1 sr)
  double value() const { return L_cd_m2 * L_cd_m2 * omega_sr / (p * p); }
};

struct ViewTerm {
  std::string luminaire;  // the luminaire's label
  GlareTerm term;
};

struct ViewResult {
  Vec3 direction{1, 0, 0};      // unit line of sight
  std::optional<double> UGR;    // none when no luminaire counts in this view
  double Lb_cd_m2 = 0.0;        // background luminance, E_indirect / pi
  double E_indirect_lx = 0.0;   // indirect illuminance at the eye facing the view (initial)
  std::vector<ViewTerm> terms;  // the luminaires that count, in the scene's order
};

struct ObserverResult {
  Vec3 at{0.0};
  std::vector<ViewResult> views;
};

}  // namespace luxgrid::calc::glare
