#pragma once
/// @file
/// nlohmann::json values as Python objects (statistics, step records, scene settings).

#include <pybind11/pybind11.h>

#include <nlohmann/json_fwd.hpp>

namespace tailor::python {

namespace py = pybind11;

/// The Python value of `json`: dict, list, str, int, float, bool or None.
py::object to_python(const nlohmann::json& json);

/// `object` (a dict, list, str, number, bool or None) as JSON, through Python's `json`
/// module so that NaN and other values JSON lacks are rejected. Throws ValueError naming
/// `name`.
nlohmann::json to_json_value(py::handle object, const char* name);

}  // namespace tailor::python
