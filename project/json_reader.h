#pragma once
// A thin walker over nlohmann::json that knows where it is: every value carries its JSON pointer,
// so every complaint names the place (`office.json /luminaires/3/rotation: expected 3 numbers,
// got 2`), and every key nobody read is reported (docs/reliability.md, "Error messages").
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "project/json_positions.h"
#include "util/error.h"
#include "util/format.h"
#include "util/robust_math.h"

namespace luxgrid::project {

class JsonValue;

// A parsed JSON document being read, and what its readers have asked for so far. Every member
// a reader takes (JsonValue::at, find) is marked "queried"; report_unqueried() then names, by
// its JSON pointer, any member nobody read: a misspelt or unsupported key is an error, found
// from the reads themselves rather than from a list kept beside them (the same idea as
// pbrt-v4's ParameterDictionary::ReportUnused and Mitsuba 3's Properties::unqueried).
class JsonDocument {
 public:
  // `root` must outlive the document, and the document every value taken from it. Given the
  // positions the parse recorded for `root` (project/json_positions.h), every value's location
  // has its line and column too.
  JsonDocument(const nlohmann::json& root, std::string file,
               const JsonPositions* positions = nullptr)
      : root_(&root), file_(std::move(file)), positions_(positions) {}
  JsonDocument(const JsonDocument&) = delete;
  JsonDocument& operator=(const JsonDocument&) = delete;

  JsonValue root() const;
  const std::string& file() const { return file_; }

 private:
  friend class JsonValue;
  void mark_queried(const nlohmann::json& member) const { queried_.insert(&member); }
  void mark_asked(const nlohmann::json& object, const char* key) const;
  bool queried(const nlohmann::json& member) const { return queried_.count(&member) != 0; }
  // The keys asked of `object` that it does not have, in the order first asked.
  std::vector<std::string> asked_absent(const nlohmann::json& object) const;

  const nlohmann::json* root_;
  std::string file_;
  const JsonPositions* positions_;
  mutable std::unordered_set<const nlohmann::json*> queried_;  // member values read
  // Keys asked of an object that it lacks (for the list of keys a message offers), by name
  // interned once per document: a 20 000-luminaire project asks each for the same few keys.
  mutable std::unordered_map<const nlohmann::json*, std::vector<const std::string*>> absent_;
  mutable std::unordered_set<std::string> names_;
};

// One value of a JsonDocument: knows its JSON pointer, so every complaint names the place.
class JsonValue {
 public:
  JsonValue(const nlohmann::json& value, const JsonDocument& doc, std::string pointer)
      : value_(&value), doc_(&doc), pointer_(std::move(pointer)) {}

  const nlohmann::json& raw() const { return *value_; }
  const std::string& pointer() const { return pointer_; }
  // The file, the line and column where this value begins (when the document has positions) and
  // its pointer ("/" for the root).
  SourceLocation location() const;
  [[noreturn]] void fail(const std::string& what) const;

  bool is_object() const { return value_->is_object(); }
  bool is_string() const { return value_->is_string(); }
  bool is_number() const { return value_->is_number(); }
  bool is_array() const { return value_->is_array(); }

  // Objects. expect_object checks the type only: which keys are allowed follows from what is
  // read (report_unqueried).
  void expect_object() const;
  bool has(const char* key) const;                       // asks, does not mark as read
  JsonValue at(const char* key) const;                   // required member, marked as read
  std::optional<JsonValue> find(const char* key) const;  // optional member, marked as read
  // Marks an optional member read without looking at it: notes for people, any content.
  void accept_any(const char* key) const { find(key); }
  // Throws InputError at the first member, in document order, of this value or anything inside
  // it that no reader has taken: `p.json /rooms/0/heigth: unknown key "heigth" (expected one
  // of: floor_z, height, name, ...)`, listing the keys read or asked for in that object.
  void report_unqueried() const;
  // Arrays.
  std::vector<JsonValue> items() const;  // requires an array
  JsonValue item(size_t index) const;

  std::string as_string() const;
  double as_number() const;  // finite
  int as_int() const;
  bool as_bool() const;
  double as_number_in(double lo, double hi) const;
  double as_positive() const;      // > 0
  double as_non_negative() const;  // >= 0
  Vec3 as_vec3() const;
  Vec2 as_vec2() const;
  std::vector<double> as_numbers(size_t count) const;

 private:
  JsonValue member(const std::string& key) const;

  const nlohmann::json* value_;
  const JsonDocument* doc_;
  std::string pointer_;
};

inline JsonValue JsonDocument::root() const { return JsonValue(*root_, *this, ""); }

std::string json_type_name(const nlohmann::json& j);

// RFC 6901 escaping of a key inside a JSON pointer ("a/b" -> "a~1b", "~" -> "~0").
std::string json_pointer_escape(const std::string& key);

}  // namespace luxgrid::project
