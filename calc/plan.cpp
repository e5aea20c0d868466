#include "calc/plan.h"

#include <cstdlib>

#include "util/error.h"

namespace luxgrid::calc {

nearfield::Model near_model_for(const Settings& settings) {
  using nearfield::Model;
  const std::string& name = settings.near_field_model;
  if (name.empty()) {
    switch (settings.quality) {
      case Quality::draft: return Model::far_field();
      case Quality::standard: return Model::standard();
      case Quality::high: return Model::high();
      case Quality::reference: return Model::reference();
    }
  }
  if (auto model = near_model_named(name)) return *model;
  throw InputError(SourceLocation{"", 0, 0, "/settings/near_field_model"},
                   "unknown model \"" + name + "\" (expected " + kNearFieldModelNames + ")");
}

Plan make_plan(const Scene& scene) {
  Plan plan;
  const Settings& s = scene.settings;
  plan.near_model = near_model_for(s);
  if (s.quality == Quality::draft && s.near_field_model.empty()) {
    plan.near_switch = nearfield::NearFieldSwitch::never;
    plan.notes.push_back("quality draft: far-field point model at every distance");
  } else if (s.near_field == NearFieldMode::never) {
    plan.near_switch = nearfield::NearFieldSwitch::never;
  } else if (s.near_field == NearFieldMode::always ||
             (s.quality == Quality::reference && s.near_field_model.empty())) {
    plan.near_switch = nearfield::NearFieldSwitch::always;
  } else {
    plan.near_switch = nearfield::NearFieldSwitch::automatic;
  }
  plan.direct = "not computed yet";
  plan.indirect_decision = indirect::decide_indirect(scene);
  plan.indirect = plan.indirect_decision.reason;
  std::string reason;
  plan.visibility_test = make_visibility(scene, reason);
  plan.visibility = reason;
  if (plan.visibility_test) {
    plan.visibility +=
        "; near-field pairs test visibility per quadrature node (soft shadows of "
        "area luminaires), far-field pairs from the centre of the opening";
  }
  return plan;
}

std::string describe_direct(const Plan& plan, const DirectCounts& c) {
  const std::string model = nearfield::to_string(plan.near_model);
  std::string out;
  switch (plan.near_switch) {
    case nearfield::NearFieldSwitch::never: out = "far-field point model everywhere"; break;
    case nearfield::NearFieldSwitch::always:
      out = "near-field model " + model + " at every distance";
      break;
    case nearfield::NearFieldSwitch::automatic:
      if (!plan.near_far_per_emitter.empty()) {
        out = "hybrid by an error bound (near-field " + model +
              " wherever the far-field point model is "
              "not within the quality's promise, measured per emitter and direction; the fixed "
              "rule of a "
              "few nodes across the opening where it is within the promise and the far field is "
              "not; each "
              "blended over 1.25 x its distance)";
      } else {
        out = "hybrid by the five-times rule (near-field " + model + " closer than " +
              std::to_string(static_cast<int>(nearfield::kBlendStart)) +
              " x the emitter size, far-field beyond " +
              std::to_string(static_cast<int>(nearfield::kBlendEnd)) + " x, blended between)";
      }
      break;
  }
  out += ": " + std::to_string(c.near) + " luminaire-point pairs near-field, " +
         std::to_string(c.blended) + " blended, " + std::to_string(c.far) + " far-field, " +
         std::to_string(c.point_sources) + " from point sources (exact point model)";
  if (c.fixed_rule + c.fixed_blended > 0)
    out += "; of the near-field and blended pairs " + std::to_string(c.fixed_rule) +
           " by the fixed rule, " + std::to_string(c.fixed_blended) +
           " blending it into the near-field model";
  for (const auto& line : plan.near_far_per_emitter) out += "; " + line;
  if (!plan.intensity_lookup_per_distribution.empty()) {
    out += "; far-field pairs and the first bounce look intensities up in:";
    for (size_t k = 0; k < plan.intensity_lookup_per_distribution.size(); ++k)
      out += (k == 0 ? " " : "; ") + plan.intensity_lookup_per_distribution[k];
  }
  return out;
}

}  // namespace luxgrid::calc
