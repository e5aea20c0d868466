#include "calc/plan.h"

#include <cstdlib>

#include "util/error.h"

namespace luxgrid::calc {

namespace {

// A whole number after `prefix` in `name` ("lambert-3" -> 3), or -1.
int suffix_number(const std::string& name, const std::string& prefix) {
  if (name.rfind(prefix, 0) != 0 || name.size() == prefix.size()) return -1;
  const std::string digits = name.substr(prefix.size());
  for (char c : digits) {
    if (c < '0' || c > '9') return -1;
  }
  return digits.size() > 6 ? -1 : std::atoi(digits.c_str());
}

}  // namespace

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
  if (name == "paper") return Model::paper_cubature();
  if (name == "far-field") return Model::far_field();
  if (name == "standard") return Model::standard();
  if (name == "high") return Model::high();
  if (name == "adaptive") return Model::adaptive(1e-3);
  if (name == "reference") return Model::reference();
  if (int k = suffix_number(name, "subdivided-"); k >= 0 && k <= 6) return Model::subdivided(k);
  if (int k = suffix_number(name, "lambert-"); k >= 0 && k <= 6)
    return Model::lambert_subdivided(k);
  throw InputError(
      "/settings/near_field_model: unknown model \"" + name +
      "\" (expected paper, far-field, standard, high, adaptive, reference, subdivided-K or "
      "lambert-K with K from 0 to 6)");
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
    plan.visibility += "; near-field pairs test visibility per quadrature node (soft shadows of "
                       "area luminaires), far-field pairs from the centre of the opening";
  }
  return plan;
}

std::string describe_direct(const Plan& plan, const DirectCounts& c) {
  const std::string model = nearfield::to_string(plan.near_model);
  std::string out;
  switch (plan.near_switch) {
    case nearfield::NearFieldSwitch::never: out = "far-field point model everywhere"; break;
    case nearfield::NearFieldSwitch::always: out = "near-field model " + model + " at every distance"; break;
    case nearfield::NearFieldSwitch::automatic:
      if (!plan.near_far_per_emitter.empty()) {
        out = "hybrid by an error bound (near-field " + model + " wherever the far-field point model is "
              "not within the quality's promise, measured per emitter and direction; the fixed rule of a "
              "few nodes across the opening where it is within the promise and the far field is not; each "
              "blended over 1.25 x its distance)";
      } else {
        out = "hybrid by the five-times rule (near-field " + model + " closer than " +
              std::to_string(static_cast<int>(nearfield::kBlendStart)) + " x the emitter size, far-field beyond " +
              std::to_string(static_cast<int>(nearfield::kBlendEnd)) + " x, blended between)";
      }
      break;
  }
  out += ": " + std::to_string(c.near) + " luminaire-point pairs near-field, " + std::to_string(c.blended) +
         " blended, " + std::to_string(c.far) + " far-field, " + std::to_string(c.point_sources) +
         " from point sources (exact point model)";
  if (c.fixed_rule + c.fixed_blended > 0)
    out += "; of the near-field and blended pairs " + std::to_string(c.fixed_rule) + " by the fixed rule, " +
           std::to_string(c.fixed_blended) + " blending it into the near-field model";
  for (const auto& line : plan.near_far_per_emitter) out += "; " + line;
  return out;
}

}  // namespace luxgrid::calc
