#pragma once
/// @file
/// Counts and times of each pipeline stage for one step.

#include <cstdint>
#include <nlohmann/json_fwd.hpp>

namespace tailor {

/// Per-stage statistics of one detection step (counts are exact, times in milliseconds).
struct DetectionStats {
  // High level.
  std::int64_t boxes_refitted = 0;            ///< 1 when the step refitted the BVH's boxes (a
                                              ///< step whose root is certified needs none);
                                              ///< summed, the steps that did
  std::int64_t node_pairs_visited = 0;        ///< BVH node pairs whose boxes were tested
  std::int64_t nodes_culled_by_cones = 0;     ///< nodes whose self-test the normal cone skipped
  std::int64_t contour_tests = 0;             ///< contour tests run (the node's mask was not empty)
  std::int64_t contour_tests_failed = 0;      ///< contour tests that could not certify
  std::int64_t radial_pairs_culled = 0;       ///< CTPs radial view removed
  std::int64_t clusters_classified = 0;       ///< radial-view clusters classified (lazily:
                                              ///< only where a kept pair needed it)
  std::int64_t clusters_certified = 0;        ///< radial-view clusters skipped whole
  std::int64_t radial_positive = 0;           ///< radial view: triangles (real + ghost) facing
  std::int64_t radial_negative = 0;           ///<   their observer, facing away, or neither
  std::int64_t radial_undetermined = 0;       ///<   over the whole step (classified clusters)
  std::int64_t candidate_triangle_pairs = 0;  ///< CTPs emitted
  std::int64_t isolated_vf_pairs = 0;         ///< VF pairs of the isolated set
  std::int64_t isolated_ee_pairs = 0;         ///< EE pairs of the isolated set
  // Low level: VF / EE pairs after each stage.
  std::int64_t vf_generated = 0, ee_generated = 0;        ///< from CTPs + isolated set
  std::int64_t vf_after_boxes = 0, ee_after_boxes = 0;    ///< survived primitive boxes
  std::int64_t vf_after_filter = 0, ee_after_filter = 0;  ///< survived the DNF filter
  std::int64_t vf_after_projection = 0,
               ee_after_projection = 0;             ///< survived the projection filter
  std::int64_t vf_tested = 0, ee_tested = 0;        ///< sent to the exact CCD
  std::int64_t vf_colliding = 0, ee_colliding = 0;  ///< collisions found
  std::int64_t ccd_exact_fallbacks = 0;             ///< queries the exact path decided
  // Times (ms).
  double refit_ms = 0, traversal_ms = 0, radial_view_ms = 0, pair_generation_ms = 0, ccd_ms = 0,
         total_ms = 0;

  /// Adds another step's counts and times (for means over many steps).
  DetectionStats& operator+=(const DetectionStats& other);
};

/// JSON object with every field of `stats`.
void to_json(nlohmann::json& json, const DetectionStats& stats);

}  // namespace tailor
