#pragma once
// A thin walker over nlohmann::json that knows where it is: every value carries its JSON pointer,
// so every complaint names the place (`office.json /luminaires/3/rotation: expected 3 numbers,
// got 2`), and objects reject keys nobody asked for (docs/reliability.md).
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "util/robust_math.h"

namespace luxgrid::calc {

class JsonValue {
 public:
  JsonValue(const nlohmann::json& value, std::string file, std::string pointer)
      : value_(&value), file_(std::move(file)), pointer_(std::move(pointer)) {}

  const nlohmann::json& raw() const { return *value_; }
  const std::string& pointer() const { return pointer_; }
  std::string where() const;  // "file /pointer"
  [[noreturn]] void fail(const std::string& what) const;

  bool is_object() const { return value_->is_object(); }
  bool is_string() const { return value_->is_string(); }
  bool is_number() const { return value_->is_number(); }
  bool is_array() const { return value_->is_array(); }

  // Objects: checks it is an object whose keys are all in `allowed`.
  void expect_object(std::initializer_list<const char*> allowed) const;
  bool has(const char* key) const;
  JsonValue at(const char* key) const;                 // required member
  std::optional<JsonValue> find(const char* key) const;  // optional member
  // Arrays.
  std::vector<JsonValue> items() const;  // requires an array
  JsonValue item(size_t index) const;

  std::string as_string() const;
  double as_number() const;  // finite
  int as_int() const;
  bool as_bool() const;
  double as_number_in(double lo, double hi) const;
  double as_positive() const;     // > 0
  double as_non_negative() const;  // >= 0
  Vec3 as_vec3() const;
  Vec2 as_vec2() const;
  std::vector<double> as_numbers(size_t count) const;

 private:
  const nlohmann::json* value_;
  std::string file_;
  std::string pointer_;
};

std::string json_type_name(const nlohmann::json& j);

// A number for a message: %g, so 0 and 1 print as "0" and "1" and 1e9 as "1e+09".
std::string number_text(double x);

// RFC 6901 escaping of a key inside a JSON pointer ("a/b" -> "a~1b", "~" -> "~0").
std::string json_pointer_escape(const std::string& key);

}  // namespace luxgrid::calc
