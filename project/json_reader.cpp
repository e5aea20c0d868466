#include "project/json_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "util/error.h"

namespace luxgrid::project {

std::string json_pointer_escape(const std::string& key) {
  std::string out;
  for (char c : key) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

std::string json_type_name(const nlohmann::json& j) {
  if (j.is_number()) return "a number";
  if (j.is_string()) return "a string";
  if (j.is_boolean()) return "a boolean";
  if (j.is_array()) return "an array";
  if (j.is_object()) return "an object";
  return "null";
}

void JsonDocument::mark_asked(const nlohmann::json& object, const char* key) const {
  const std::string* name = &*names_.insert(key).first;
  auto& asked = absent_[&object];
  if (std::find(asked.begin(), asked.end(), name) == asked.end()) asked.push_back(name);
}

std::vector<std::string> JsonDocument::asked_absent(const nlohmann::json& object) const {
  std::vector<std::string> out;
  const auto it = absent_.find(&object);
  if (it != absent_.end()) {
    for (const std::string* name : it->second) out.push_back(*name);
  }
  return out;
}

namespace {

// Levenshtein distance of two short keys, ignoring case: a key given within 2 edits of a missing
// one ("heigth" for "height", "Height") is most likely that key misspelt.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}
constexpr std::size_t kMisspeltEdits = 2;

}  // namespace

SourceLocation JsonValue::location() const {
  TextPosition at;
  if (doc_->positions_)
    at = pointer_.empty() ? doc_->positions_->root() : doc_->positions_->of(*value_);
  return SourceLocation{doc_->file(), at.line, at.column,
                        pointer_.empty() ? std::string("/") : pointer_};
}

void JsonValue::fail(const std::string& what) const { throw InputError(location(), what); }

void JsonValue::expect_object() const {
  if (!value_->is_object()) fail("expected an object, got " + json_type_name(*value_));
}

bool JsonValue::has(const char* key) const {
  if (!value_->is_object()) return false;
  if (value_->contains(key)) return true;
  doc_->mark_asked(*value_, key);
  return false;
}

JsonValue JsonValue::member(const std::string& key) const {
  const nlohmann::json& v = *value_->find(key);
  doc_->mark_queried(v);
  return JsonValue(v, *doc_, pointer_ + "/" + json_pointer_escape(key));
}

JsonValue JsonValue::at(const char* key) const {
  if (!has(key)) {
    std::string hint;
    if (value_->is_object()) {
      for (const auto& [given, v] : value_->items()) {
        if (!doc_->queried(v) && edit_distance(given, key) <= kMisspeltEdits) {
          hint = " (the object has \"" + given + "\": misspelt?)";
          break;
        }
      }
    }
    fail(std::string("missing required key \"") + key + "\"" + hint);
  }
  return member(key);
}

std::optional<JsonValue> JsonValue::find(const char* key) const {
  if (!has(key)) return std::nullopt;
  return member(key);
}

void JsonValue::report_unqueried() const {
  if (value_->is_array()) {
    for (size_t i = 0; i < value_->size(); ++i) item(i).report_unqueried();
    return;
  }
  if (!value_->is_object()) return;
  for (const auto& [key, v] : value_->items()) {
    if (doc_->queried(v)) continue;
    // The keys this object was read for: those taken, then those asked for and absent.
    std::vector<std::string> expected;
    for (const auto& [k, other] : value_->items()) {
      if (doc_->queried(other)) expected.push_back(k);
    }
    for (auto& k : doc_->asked_absent(*value_)) expected.push_back(std::move(k));
    std::sort(expected.begin(), expected.end());
    std::string list;
    for (const auto& k : expected) list += (list.empty() ? "" : ", ") + k;
    const JsonValue unknown(v, *doc_, pointer_ + "/" + json_pointer_escape(key));
    throw InputError(unknown.location(), "unknown key \"" + key + "\"" +
                                             (list.empty() ? std::string(" (nothing is read here)")
                                                           : " (expected one of: " + list + ")"));
  }
  for (const auto& [key, v] : value_->items()) member(key).report_unqueried();
}

std::vector<JsonValue> JsonValue::items() const {
  if (!value_->is_array()) fail("expected an array, got " + json_type_name(*value_));
  std::vector<JsonValue> out;
  for (size_t i = 0; i < value_->size(); ++i) out.push_back(item(i));
  return out;
}

JsonValue JsonValue::item(size_t index) const {
  return JsonValue((*value_)[index], *doc_, pointer_ + "/" + std::to_string(index));
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
  if (x != std::floor(x) || std::abs(x) > 1e9)
    fail("expected a whole number, got " + value_->dump());
  return static_cast<int>(x);
}

bool JsonValue::as_bool() const {
  if (!value_->is_boolean()) fail("expected true or false, got " + json_type_name(*value_));
  return value_->get<bool>();
}

double JsonValue::as_number_in(double lo, double hi) const {
  const double x = as_number();
  if (x < lo || x > hi) {
    fail("expected a number in [" + number_text(lo) + ", " + number_text(hi) + "], got " +
         value_->dump());
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

}  // namespace luxgrid::project
