#include "json_objects.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <string>

namespace tailor::python {

py::object to_python(const nlohmann::json& json) {
  switch (json.type()) {
    case nlohmann::json::value_t::object: {
      py::dict dict;
      for (const auto& [key, value] : json.items()) dict[py::str(key)] = to_python(value);
      return dict;
    }
    case nlohmann::json::value_t::array: {
      py::list list;
      for (const auto& value : json) list.append(to_python(value));
      return list;
    }
    case nlohmann::json::value_t::string:
      return py::str(json.get<std::string>());
    case nlohmann::json::value_t::boolean:
      return py::bool_(json.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(json.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(json.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float:
      return py::float_(json.get<double>());
    default:
      return py::none();
  }
}

nlohmann::json to_json_value(py::handle object, const char* name) {
  std::string text;
  try {
    text = py::module_::import("json")
               .attr("dumps")(object, py::arg("allow_nan") = false)
               .cast<std::string>();
  } catch (const py::error_already_set& e) {
    throw py::value_error(fmt::format("{} is not JSON data: {}", name, e.what()));
  }
  return nlohmann::json::parse(text);
}

}  // namespace tailor::python
