#pragma once
/// @file
/// Which culling stages a SelfCollisionDetector runs; presets are the paper's Table 1 rows.

#include <string>
#include <string_view>
#include <vector>

namespace tailor {

/// Switches for every culling stage. Every combination reports the same collisions.
struct DetectionConfig {
  bool normal_cones = true;  ///< skip nodes certified by continuous normal bounds (direction masks)
  bool contour_test = true;  ///< require the contour test for cone culling (never off by default)
  bool adjacency_culling =
      true;  ///< never emit triangle pairs sharing a vertex; use the isolated set
  bool feature_assignment = true;  ///< representative triangles (Curtis et al. 2008)
  bool primitive_boxes = true;     ///< swept boxes of vertex/edge/face pairs
  bool coplanarity_filter = true;  ///< non-coplanarity (DNF) filter
  bool projection_filter = true;   ///< projection filter (candidates/projection_filter.hpp)
  bool radial_view = true;         ///< radial-view culling where observers are given
  int threads = 0;                 ///< 0: all hardware threads
  /// Radial view: classify every cluster each step, as the paper does, instead of only the
  /// clusters a kept pair needs (radial_view_culling.hpp). The same pairs are culled either
  /// way; this only fills the statistics radial_positive / negative / undetermined of
  /// every step, at the cost of the O(faces) classification the lazy way avoids.
  bool classify_every_cluster = false;
  /// Copy the step's candidate triangle pairs into DetectionResult (for pictures and
  /// viewers; off by default because it costs memory at scale).
  bool keep_candidate_pairs = false;

  /// `basic`, `curtis`, `tang` or `paper`; throws InputError naming the bad name.
  static DetectionConfig preset(std::string_view name);
  /// Names accepted by preset().
  static std::vector<std::string> preset_names();
};

}  // namespace tailor
