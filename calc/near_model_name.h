#pragma once
// Near-field models by the names a project gives them (settings.near_field_model). A file of its
// own so that the project loader checks a name without linking the planner.
#include <optional>
#include <string>

#include "calc/nearfield/illuminance.h"

namespace luxgrid::calc {

// The near-field model named `name` ("paper", "standard", "high", "reference", "far-field",
// "subdivided-K", "lambert-K", "adaptive"), or nothing for an unknown name. The
// project loader refuses an unknown settings.near_field_model with this, naming the file.
std::optional<nearfield::Model> near_model_named(const std::string& name);
// The names near_model_named knows, for messages.
inline constexpr const char* kNearFieldModelNames =
    "paper, far-field, standard, high, adaptive, reference, subdivided-K or lambert-K with K from "
    "0 "
    "to 6";

}  // namespace luxgrid::calc
