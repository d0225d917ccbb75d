#pragma once
/// @file
/// The options of each pipeline stage that a DetectionConfig selects.

#include "tailor/candidates/primitive_pair_generator.hpp"
#include "tailor/culling/bvh_traversal.hpp"
#include "tailor/detection/detection_config.hpp"

namespace tailor {

/// The high-level switches of `config`.
inline TraversalOptions traversal_options(const DetectionConfig& config) {
  return {config.normal_cones, config.contour_test, config.adjacency_culling};
}

/// The low-level switches of `config`.
inline LowLevelOptions low_level_options(const DetectionConfig& config) {
  LowLevelOptions options;
  options.triangle_filter = config.triangle_filter;
  options.direction_filter = config.direction_filter;
  options.feature_assignment = config.feature_assignment;
  options.primitive_boxes = config.primitive_boxes;
  options.coplanarity_filter = config.coplanarity_filter;
  options.projection_filter = config.projection_filter;
  options.adjacency_culling = config.adjacency_culling;
  return options;
}

}  // namespace tailor
