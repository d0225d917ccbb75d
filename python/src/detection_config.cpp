/// @file
/// `tailor.DetectionConfig`: one property per setting of kDetectionSettings (with its help,
/// default, range and effect as the docstring), `__repr__`, `to_dict()` and `settings()`;
/// and `DetectionResult.stat_fields()`'s list, from kDetectionStatFields.

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <cctype>
#include <nlohmann/json.hpp>
#include <string>
#include <type_traits>

#include "bindings.hpp"
#include "json_objects.hpp"
#include "tailor/detection/detection_stats.hpp"

namespace tailor::python {
namespace {

template <class T>
using MemberValue =
    std::remove_cvref_t<decltype(std::declval<DetectionConfig>().*std::declval<T>())>;

// A value as Python writes it.
template <class T>
std::string python_literal(T value) {
  if constexpr (std::is_same_v<T, bool>) {
    return value ? "True" : "False";
  } else if constexpr (std::is_same_v<T, double>) {
    const std::string text = fmt::format("{}", value);  // repr keeps a whole number's ".0"
    return text.find_first_of(".en") == std::string::npos ? text + ".0" : text;
  } else {
    return fmt::format("{}", value);
  }
}

std::string range_text(const DetectionSetting& setting) {
  if (std::holds_alternative<bool DetectionConfig::*>(setting.member)) return "";
  if (setting.max == kUnbounded) return fmt::format(", ≥ {}", setting.min);
  return fmt::format(", in [{}, {}]", setting.min, setting.max);
}

// The property's docstring: the help line, default, range and effect.
std::string setting_doc(const DetectionSetting& setting) {
  static const DetectionConfig defaults;
  const std::string value =
      std::visit([](auto member) { return python_literal(defaults.*member); }, setting.member);
  std::string doc = fmt::format("{}. Default {}{}; {}", setting.help, value, range_text(setting),
                                to_string(setting.effect));
  if (!setting.cli.empty()) doc += fmt::format(" (CLI --{})", setting.cli);
  doc[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(doc[0])));
  return doc + ".";
}

template <class Member>
void bind_setting(py::class_<DetectionConfig>& cls, const DetectionSetting& setting,
                  Member member) {
  using T = MemberValue<Member>;
  const double min = setting.min, max = setting.max;
  const std::string_view name = setting.name;
  cls.def_property(
      setting.name.data(),  // a string literal: NUL-terminated
      [member](const DetectionConfig& c) { return c.*member; },
      [member, min, max, name](DetectionConfig& c, T value) {
        if constexpr (!std::is_same_v<T, bool>) {
          if (!(static_cast<double>(value) >= min && static_cast<double>(value) <= max)) {
            throw py::value_error(fmt::format(
                "{} must be {}, got {}", name,
                max == kUnbounded ? fmt::format("≥ {}", min) : fmt::format("in [{}, {}]", min, max),
                value));
          }
        }
        c.*member = value;
      },
      setting_doc(setting).c_str());
}

std::string repr(const DetectionConfig& config) {
  std::string text = "tailor.DetectionConfig(";
  const char* separator = "";
  for (const DetectionSetting& setting : kDetectionSettings) {
    std::visit(
        [&](auto member) {
          text += fmt::format("{}{}={}", separator, setting.name, python_literal(config.*member));
        },
        setting.member);
    separator = ", ";
  }
  return text + ")";
}

py::list settings_list() {
  py::list list;
  for (const DetectionSetting& setting : kDetectionSettings) {
    py::dict entry;
    entry["name"] = std::string(setting.name);
    static const DetectionConfig defaults;
    std::visit([&](auto member) { entry["default"] = defaults.*member; }, setting.member);
    entry["min"] = setting.min;
    entry["max"] = setting.max;
    entry["cli"] = std::string(setting.cli);
    entry["effect"] = std::string(to_string(setting.effect));
    entry["help"] = std::string(setting.help);
    list.append(entry);
  }
  return list;
}

}  // namespace

py::list stat_fields() {
  py::list list;
  for (const DetectionStatField& field : kDetectionStatFields) {
    py::dict entry;
    entry["name"] = std::string(field.name);
    entry["unit"] = field.is_time() ? "ms" : "count";
    entry["stage"] = std::string(field.stage);
    entry["help"] = std::string(field.help);
    list.append(entry);
  }
  return list;
}

void bind_detection_config(py::module_& m) {
  py::class_<DetectionConfig> cls(
      m, "DetectionConfig",
      "Settings of the detector: a switch per culling stage, threads, and what the result "
      "holds. Every switch changes only the work (each preset reports exactly the "
      "brute-force collisions) except contour_test: off, with normal_cones on, it can miss "
      "collisions (for comparison only). DetectionConfig() is the paper preset; settings() "
      "lists every setting with its default, range and effect.");
  cls.def(py::init<>())
      .def_static("preset", &DetectionConfig::preset, py::arg("name"),
                  "basic, curtis, tang or paper (the paper's Table 1 rows).")
      .def_static("preset_names", &DetectionConfig::preset_names)
      .def_static("settings", &settings_list,
                  "Every setting as a dict: name, default, min, max, cli, effect (work only, "
                  "output only, unsound when off, defines the result), help.");
  for (const DetectionSetting& setting : kDetectionSettings) {
    std::visit([&](auto member) { bind_setting(cls, setting, member); }, setting.member);
  }
  cls.def(
         "to_dict", [](const DetectionConfig& c) { return to_python(nlohmann::json(c)); },
         "Every setting as a dict (as `tailor detect --json` writes it).")
      .def("__repr__", &repr);
}

DetectionConfig detection_config(py::handle method, int threads) {
  if (threads < 0) throw py::value_error(fmt::format("threads must be ≥ 0, got {}", threads));
  DetectionConfig config;
  if (py::isinstance<DetectionConfig>(method)) {
    config = method.cast<DetectionConfig>();
    if (threads > 0) config.threads = threads;
  } else if (py::isinstance<py::str>(method)) {
    config = DetectionConfig::preset(method.cast<std::string>());
    config.threads = threads;
  } else {
    throw py::value_error("method must be a preset name (str) or a DetectionConfig");
  }
  return config;
}

}  // namespace tailor::python
