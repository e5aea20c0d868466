#pragma once
// Where each value of a parsed JSON document begins in its text, so a complaint about a value
// names its line and column as well as its JSON pointer (`office.json:12:15 /rooms/0/height:
// expected a number, got a string`; docs/reliability.md, "Error messages"). The safe parse
// (project/safe_json.h) fills it in while it reads.
//
// Values are known by their address in the DOM: nlohmann keeps an object's members in map nodes
// and an array's elements in one buffer, neither of which moves once the parse is done, and
// moving a document moves only its root. So the positions hold for the document as parsed (and
// moved), not for a copy: a value they do not know gets line 0 (its pointer alone). One entry
// per value, 16 bytes, less than the value itself takes in the DOM (24 bytes with
// JSON_DIAGNOSTICS), so a document within the size limit keeps its positions within the same
// bound.
#include <algorithm>
#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

namespace luxgrid::project {

// A line and column in a text, 1-based, the column in bytes; 0 when not known.
struct TextPosition {
  int line = 0;
  int column = 0;
};

class JsonPositions {
 public:
  // The position of `value`, a value of the document these positions were recorded for; the
  // root is known apart (the parse returns it by moving it).
  TextPosition of(const nlohmann::json& value) const {
    const auto it = std::lower_bound(
        entries_.begin(), entries_.end(), &value,
        [](const Entry& e, const nlohmann::json* v) { return std::less<>()(e.value, v); });
    if (it == entries_.end() || it->value != &value) return {};
    return {static_cast<int>(it->line), static_cast<int>(it->column)};
  }
  TextPosition root() const { return root_; }

  // For the parse: record where a value begins, then sort once the document is complete.
  void add(const nlohmann::json* value, TextPosition at) {
    entries_.push_back(
        {value, static_cast<std::uint32_t>(at.line), static_cast<std::uint32_t>(at.column)});
  }
  void set_root(TextPosition at) { root_ = at; }
  void finish() {
    std::sort(entries_.begin(), entries_.end(),
              [](const Entry& a, const Entry& b) { return std::less<>()(a.value, b.value); });
  }

 private:
  struct Entry {
    const nlohmann::json* value;
    std::uint32_t line, column;
  };
  std::vector<Entry> entries_;  // sorted by address after finish()
  TextPosition root_;
};

}  // namespace luxgrid::project
