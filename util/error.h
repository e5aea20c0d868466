#pragma once
// One error type for the whole library: it carries a message a user can act on, already
// naming the file and line or the JSON pointer. Only cli/ catches it (docs/architecture.md, "Errors").
#include <stdexcept>
#include <string>

namespace luxgrid {

// Input the user can fix (bad project file, unreadable photometry, impossible geometry).
// The CLI maps it to exit code 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A calculation that could not be completed although its input was accepted. Exit code 1.
class CalculationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace luxgrid
