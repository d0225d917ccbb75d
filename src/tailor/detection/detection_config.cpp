#include "tailor/detection/detection_config.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <type_traits>

#include "tailor/geometry/error.hpp"

namespace tailor {

DetectionConfig DetectionConfig::preset(std::string_view name) {
  DetectionConfig config;
  // Cumulative, as the rows of the paper's Table 1.
  config.normal_cones = config.contour_test = config.adjacency_culling = false;
  config.feature_assignment = config.primitive_boxes = config.coplanarity_filter = false;
  config.projection_filter = config.radial_view = config.triangle_filter = false;
  config.direction_filter = config.diagonal_bounds = config.thickness_filter = false;
  if (name == "basic") return config;
  config.feature_assignment = true;
  if (name == "curtis") return config;
  config.normal_cones = config.contour_test = true;
  config.adjacency_culling = true;
  config.coplanarity_filter = true;
  if (name == "tang") return config;
  config.primitive_boxes = true;
  config.radial_view = true;
  config.projection_filter = true;
  config.triangle_filter = true;
  config.direction_filter = true;
  config.diagonal_bounds = true;
  config.thickness_filter = true;
  if (name == "paper") return config;
  throw InputError(
      fmt::format("unknown method '{}' (expected one of: basic, curtis, tang, paper)", name));
}

std::vector<std::string> DetectionConfig::preset_names() {
  return {"basic", "curtis", "tang", "paper"};
}

std::string_view to_string(SettingEffect effect) {
  switch (effect) {
    case SettingEffect::work_only:
      return "work only";
    case SettingEffect::output_only:
      return "output only";
    case SettingEffect::unsound_when_off:
      return "unsound when off";
    case SettingEffect::defines_result:
      return "defines the result";
  }
  return "?";
}

std::string setting_value(const DetectionConfig& config, const DetectionSetting& setting) {
  return std::visit(
      [&](auto member) -> std::string {
        const auto value = config.*member;
        using Value = std::remove_cv_t<decltype(value)>;
        if constexpr (std::is_same_v<Value, bool>) {
          return value ? "true" : "false";
        } else if constexpr (std::is_same_v<Value, double>) {
          // As JSON and Python write it: a whole number keeps its ".0".
          const std::string text = fmt::format("{}", value);
          return text.find_first_of(".en") == std::string::npos ? text + ".0" : text;
        } else {
          return fmt::format("{}", value);
        }
      },
      setting.member);
}

void to_json(nlohmann::json& json, const DetectionConfig& config) {
  json = nlohmann::json::object();
  for (const DetectionSetting& setting : kDetectionSettings) {
    std::visit([&](auto member) { json[std::string(setting.name)] = config.*member; },
               setting.member);
  }
}

}  // namespace tailor
