#pragma once
// One error type for the whole library: it carries a message a user can act on and the place in
// the input it concerns. Only cli/ catches it (docs/architecture.md, "Errors").
#include <stdexcept>
#include <string>
#include <utility>

#include "util/printable.h"

namespace luxgrid {

// Where in the user's input something is: a file and, inside it, a line and column (text read
// line by line: IES, EULUMDAT, JSON syntax) and/or a JSON pointer (a value of a parsed JSON
// document). Every part is optional. It prints by one rule (docs/reliability.md, "Error
// messages"): the parts that are known, in the order file, line, column, pointer:
//   office.json:12:7: ...   panel.ies:14: ...   office.json /rooms/0/height: ...   panel.ies: ...
struct SourceLocation {
  SourceLocation() = default;
  explicit SourceLocation(std::string file_, int line_ = 0, int column_ = 0,
                          std::string pointer_ = "")
      : file(std::move(file_)), line(line_), column(column_), pointer(std::move(pointer_)) {}

  std::string file;     // as the user gave it; empty: not known
  int line = 0;         // 1-based; 0: not known
  int column = 0;       // 1-based, only with a line; 0: not known
  std::string pointer;  // RFC 6901 ("/rooms/0"; the whole document is "/"); empty: none

  bool empty() const { return file.empty() && line == 0 && pointer.empty(); }

  // "file:line:column /pointer", the known parts only.
  std::string text() const {
    std::string out = file;
    if (line > 0) {
      out += ":" + std::to_string(line);
      if (column > 0) out += ":" + std::to_string(column);
    }
    if (!pointer.empty()) out += (out.empty() ? "" : " ") + pointer;
    return out;
  }
};

// "<place>: <message>", or the message alone when the place is empty; a control character in
// either (a JSON key holding "\u0000") written as its escape (util/printable.h).
inline std::string located_message(const SourceLocation& where, const std::string& message) {
  return printable_text(where.empty() ? message : where.text() + ": " + message);
}

// Legal input that is probably a mistake (lengths in millimetres, a clockwise outline): where it
// is and what luxgrid assumed. It prints by the same rule as an InputError.
struct Warning {
  SourceLocation where;
  std::string message;

  std::string text() const { return located_message(where, message); }
};

// Input the user can fix (bad project file, unreadable photometry, impossible geometry).
// The CLI maps it to exit code 2.
class InputError : public std::runtime_error {
 public:
  InputError(SourceLocation where, const std::string& message)
      : std::runtime_error(located_message(where, message)),
        where_(std::move(where)),
        message_(message) {}
  // Input with no place to point at (a command-line value, an object named in the message).
  explicit InputError(const std::string& message) : InputError(SourceLocation{}, message) {}

  const SourceLocation& where() const { return where_; }
  const std::string& message() const { return message_; }  // what() without the place

  // The same error placed in `file` when it names no file yet (found after reading, while
  // calculating); otherwise a copy.
  InputError in_file(const std::string& file) const {
    if (!where_.file.empty()) return *this;
    SourceLocation w = where_;
    w.file = file;
    return InputError(std::move(w), message_);
  }

 private:
  SourceLocation where_;
  std::string message_;
};

// A calculation that could not be completed although its input was accepted. Exit code 1.
class CalculationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace luxgrid
