#pragma once
// What was done to the project before the calculation (the emergency scene's choices,
// calc/emergency_scene.h), as values with a code: report/plan_text.h words them, results.json
// keeps them in the plan.
#include <cstddef>
#include <string>
#include <vector>

namespace luxgrid::calc {

// One emergency luminaire's output as the project gave it (calc/scene.h, EmergencyOutput): the
// photometry entry `photometry` when set, else its own distribution scaled to `flux_lm` lumens
// when above 0, else `factor` of its own output.
struct EmergencyOutputNote {
  std::string luminaire;  // its label
  double factor = 1.0;
  double flux_lm = 0.0;
  std::string photometry;
};

struct SceneNote {
  enum class Kind {
    // The emergency scene [EN1838]: direct light only, from `luminaires` of the project's
    // `of_luminaires` luminaires (those with an emergency entry) at their emergency output;
    // `outputs` holds the first kListedOutputs of them.
    emergency_scene,
    // `observers` observers surfaces left out of the emergency scene: UGR is not an emergency
    // lighting quantity.
    observers_left_out,
  };
  static constexpr std::size_t kListedOutputs = 3;
  Kind kind = Kind::emergency_scene;
  std::size_t luminaires = 0, of_luminaires = 0, observers = 0;
  std::vector<EmergencyOutputNote> outputs;
};

}  // namespace luxgrid::calc
