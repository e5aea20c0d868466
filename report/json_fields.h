#pragma once
// Fields of results.json shared by its writer and its readers. A vector is a JSON array [x, y, z].
// The readers of results.json (report/plan_json.cpp, report/report_input_json.cpp) read an
// object's members into variables, each member required (json::at throws, and the caller names
// the JSON pointer): one helper for that shape, the members in the order given.
#include <utility>

#include <nlohmann/json.hpp>

#include "util/robust_math.h"  // Vec3

namespace luxgrid::report {

inline nlohmann::json vec3_json(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

inline void read_fields(const nlohmann::json&) {}

// read_fields(j, "name", room.name, "height", room.height, ...).
template <class T, class... Rest>
void read_fields(const nlohmann::json& j, const char* key, T& value, Rest&&... rest) {
  j.at(key).get_to(value);
  read_fields(j, std::forward<Rest>(rest)...);
}

}  // namespace luxgrid::report
