#include "calc/json_reader.h"

#include <cmath>
#include <cstdio>

#include "util/error.h"

namespace luxgrid::calc {

std::string json_pointer_escape(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

std::string number_text(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

std::string json_type_name(const nlohmann::json& j) {
  if (j.is_number()) return "a number";
  if (j.is_string()) return "a string";
  if (j.is_boolean()) return "a boolean";
  if (j.is_array()) return "an array";
  if (j.is_object()) return "an object";
  return "null";
}

std::string JsonValue::where() const {
  return file_ + " " + (pointer_.empty() ? std::string("/") : pointer_);
}

void JsonValue::fail(const std::string& what) const { throw InputError(where() + ": " + what); }

void JsonValue::expect_object(std::initializer_list<const char*> allowed) const {
  if (!value_->is_object()) fail("expected an object, got " + json_type_name(*value_));
  for (const auto& [key, _] : value_->items()) {
    bool known = false;
    for (const char* a : allowed) known = known || key == a;
    if (!known) {
      std::string list;
      for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
      throw InputError(file_ + " " + pointer_ + "/" + json_pointer_escape(key) + ": unknown key \"" + key +
                       "\" (expected one of: " + list + ")");
    }
  }
}

bool JsonValue::has(const char* key) const { return value_->is_object() && value_->contains(key); }

JsonValue JsonValue::at(const char* key) const {
  if (!has(key)) fail(std::string("missing required key \"") + key + "\"");
  return JsonValue((*value_)[key], file_, pointer_ + "/" + json_pointer_escape(key));
}

std::optional<JsonValue> JsonValue::find(const char* key) const {
  if (!has(key)) return std::nullopt;
  return at(key);
}

std::vector<JsonValue> JsonValue::items() const {
  if (!value_->is_array()) fail("expected an array, got " + json_type_name(*value_));
  std::vector<JsonValue> out;
  for (size_t i = 0; i < value_->size(); ++i) out.push_back(item(i));
  return out;
}

JsonValue JsonValue::item(size_t index) const {
  return JsonValue((*value_)[index], file_, pointer_ + "/" + std::to_string(index));
}

std::string JsonValue::as_string() const {
  if (!value_->is_string()) fail("expected a string, got " + json_type_name(*value_));
  std::string text = value_->get<std::string>();
  // Names become file names and messages, paths are opened: a control character (an escaped
  // \u0000 ends a C path early, so "a.ies\u0000.txt" would open a.ies) is never meant.
  for (size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c == 0x7F) {
      char code[8];
      std::snprintf(code, sizeof code, "U+%04X", c);
      fail(std::string("expected text without control characters, found ") + code + " at byte " +
           std::to_string(i + 1));
    }
  }
  return text;
}

double JsonValue::as_number() const {
  if (!value_->is_number()) fail("expected a number, got " + json_type_name(*value_));
  const double x = value_->get<double>();
  if (!std::isfinite(x)) fail("expected a finite number");
  return x;
}

int JsonValue::as_int() const {
  const double x = as_number();
  if (x != std::floor(x) || std::abs(x) > 1e9) fail("expected a whole number, got " + value_->dump());
  return static_cast<int>(x);
}

bool JsonValue::as_bool() const {
  if (!value_->is_boolean()) fail("expected true or false, got " + json_type_name(*value_));
  return value_->get<bool>();
}

double JsonValue::as_number_in(double lo, double hi) const {
  const double x = as_number();
  if (x < lo || x > hi) {
    fail("expected a number in [" + number_text(lo) + ", " + number_text(hi) + "], got " + value_->dump());
  }
  return x;
}

double JsonValue::as_positive() const {
  const double x = as_number();
  if (!(x > 0.0)) fail("expected a positive number, got " + value_->dump());
  return x;
}

double JsonValue::as_non_negative() const {
  const double x = as_number();
  if (x < 0.0) fail("expected a number >= 0, got " + value_->dump());
  return x;
}

std::vector<double> JsonValue::as_numbers(size_t count) const {
  if (!value_->is_array()) {
    fail("expected " + std::to_string(count) + " numbers, got " + json_type_name(*value_));
  }
  if (value_->size() != count) {
    fail("expected " + std::to_string(count) + " numbers, got " + std::to_string(value_->size()));
  }
  std::vector<double> out;
  for (size_t i = 0; i < count; ++i) out.push_back(item(i).as_number());
  return out;
}

Vec3 JsonValue::as_vec3() const {
  const auto v = as_numbers(3);
  return {v[0], v[1], v[2]};
}

Vec2 JsonValue::as_vec2() const {
  const auto v = as_numbers(2);
  return {v[0], v[1]};
}

}  // namespace luxgrid::calc
