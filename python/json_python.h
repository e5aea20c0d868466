#pragma once
// JSON values as Python objects: what the module returns as plain data (the plan, the
// requirement checks, `info`'s document, a project file's document) is built by the same code
// the CLI writes as JSON, then turned into dicts, lists, strings, numbers, booleans and None here.
#include <pybind11/pybind11.h>
#include <nlohmann/json.hpp>

namespace luxgrid::python {

// Objects come out with their keys sorted, as nlohmann::json keeps them; numbers keep their type
// (an integer stays an int, a double the same float).
pybind11::object to_python(const nlohmann::json& value);

}  // namespace luxgrid::python
