#include "tailor/detection/detection_config.hpp"

#include <fmt/format.h>

#include "tailor/geometry/error.hpp"

namespace tailor {

DetectionConfig DetectionConfig::preset(std::string_view name) {
  DetectionConfig config;
  // Cumulative, as the rows of the paper's Table 1.
  config.normal_cones = config.contour_test = config.adjacency_culling = false;
  config.feature_assignment = config.primitive_boxes = config.coplanarity_filter = false;
  config.projection_filter = config.radial_view = false;
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
  if (name == "paper") return config;
  throw InputError(
      fmt::format("unknown method '{}' (expected one of: basic, curtis, tang, paper)", name));
}

std::vector<std::string> DetectionConfig::preset_names() {
  return {"basic", "curtis", "tang", "paper"};
}

}  // namespace tailor
