#include "calc/plan.h"

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
  plan.quality = s.quality;
  plan.near_model = near_model_for(s);
  if (s.quality == Quality::draft && s.near_field_model.empty()) {
    plan.near_switch = nearfield::NearFieldSwitch::never;
    plan.near_switch_reason = NearSwitchReason::draft_quality;
  } else if (s.near_field == NearFieldMode::never) {
    plan.near_switch = nearfield::NearFieldSwitch::never;
    plan.near_switch_reason = NearSwitchReason::setting_never;
  } else if (s.near_field == NearFieldMode::always) {
    plan.near_switch = nearfield::NearFieldSwitch::always;
    plan.near_switch_reason = NearSwitchReason::setting_always;
  } else if (s.quality == Quality::reference && s.near_field_model.empty()) {
    plan.near_switch = nearfield::NearFieldSwitch::always;
    plan.near_switch_reason = NearSwitchReason::reference_quality;
  } else {
    plan.near_switch = nearfield::NearFieldSwitch::automatic;
    plan.near_switch_reason = NearSwitchReason::automatic;
  }
  plan.indirect_decision = indirect::decide_indirect(scene);
  plan.visibility_test = make_visibility(scene, plan.visibility);
  plan.scene_notes = scene.notes;
  return plan;
}

}  // namespace luxgrid::calc
