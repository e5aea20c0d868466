#include "calc/near_model_name.h"

#include <cstdlib>

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

std::optional<nearfield::Model> near_model_named(const std::string& name) {
  using nearfield::Model;
  if (name == "paper") return Model::paper_cubature();
  if (name == "far-field") return Model::far_field();
  if (name == "standard") return Model::standard();
  if (name == "high") return Model::high();
  if (name == "adaptive") return Model::adaptive(1e-3);
  if (name == "reference") return Model::reference();
  if (int k = suffix_number(name, "subdivided-"); k >= 0 && k <= 6) return Model::subdivided(k);
  if (int k = suffix_number(name, "lambert-"); k >= 0 && k <= 6)
    return Model::lambert_subdivided(k);
  return std::nullopt;
}

}  // namespace luxgrid::calc
