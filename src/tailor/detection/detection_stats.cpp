#include "tailor/detection/detection_stats.hpp"

#include <nlohmann/json.hpp>

namespace tailor {

// One list of fields keeps operator+= and to_json in step with the struct.
// clang-format off
#define TAILOR_DETECTION_STATS_FIELDS(X)                                                    \
  X(boxes_refitted)                                                                         \
  X(node_pairs_visited) X(nodes_culled_by_cones) X(contour_tests) X(contour_tests_failed)   \
  X(radial_pairs_culled) X(clusters_classified)                                            \
  X(clusters_certified) X(radial_positive) X(radial_negative) X(radial_undetermined)        \
  X(candidate_triangle_pairs) X(isolated_vf_pairs) X(isolated_ee_pairs)                     \
  X(vf_generated) X(ee_generated) X(vf_after_boxes) X(ee_after_boxes)                       \
  X(vf_after_filter) X(ee_after_filter) X(vf_after_projection) X(ee_after_projection)       \
  X(vf_tested) X(ee_tested)                                                                 \
  X(vf_colliding) X(ee_colliding) X(ccd_exact_fallbacks)                                    \
  X(refit_ms) X(traversal_ms) X(radial_view_ms) X(pair_generation_ms) X(ccd_ms) X(total_ms)
// clang-format on

DetectionStats& DetectionStats::operator+=(const DetectionStats& other) {
#define TAILOR_ADD(field) field += other.field;
  TAILOR_DETECTION_STATS_FIELDS(TAILOR_ADD)
#undef TAILOR_ADD
  return *this;
}

void to_json(nlohmann::json& json, const DetectionStats& stats) {
  json = nlohmann::json::object();
#define TAILOR_TO_JSON(field) json[#field] = stats.field;
  TAILOR_DETECTION_STATS_FIELDS(TAILOR_TO_JSON)
#undef TAILOR_TO_JSON
}

}  // namespace tailor
