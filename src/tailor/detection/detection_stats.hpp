#pragma once
/// @file
/// Counts and times of each pipeline stage for one step.
///
/// Every counter and time is declared once, in TAILOR_DETECTION_STATS below (name, stage,
/// one line of help); the struct's members, operator+=, the JSON output (CLI, Python) and
/// docs/settings.md all expand that list (docs/design.md, "Adding a setting").

#include <array>
#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <string_view>
#include <variant>

namespace tailor {

/// Every field of DetectionStats, once, in declaration order:
///   COUNT(name, stage, help)  an exact count (std::int64_t)
///   TIME(name, stage, help)   a time in milliseconds (double)
/// `stage` names the pipeline stage that fills it (docs/design.md §1); `help` is one line,
/// without a final period. A new counter also needs the line that fills it (stage_stats.cpp
/// or the detector).
// clang-format off
#define TAILOR_DETECTION_STATS(COUNT, TIME)                                                       \
  COUNT(boxes_refitted, "refit",                                                                  \
        "1 when the step refitted the BVH's boxes (a step whose root is certified needs none); "  \
        "summed, the steps that did")                                                             \
  COUNT(node_pairs_visited, "traversal", "BVH node pairs whose boxes were tested")               \
  COUNT(leaf_buckets, "traversal",                                                                \
        "small subtrees or pairs of them compared leaf by leaf, 16 or 8 leaves at a time")        \
  COUNT(nodes_culled_by_cones, "traversal", "nodes whose self-test the normal cone skipped")     \
  COUNT(contour_tests, "traversal", "contour tests run (the node's mask was not empty)")         \
  COUNT(contour_tests_failed, "traversal", "contour tests that could not certify")               \
  COUNT(radial_pairs_culled, "radial view", "candidate triangle pairs radial view removed")      \
  COUNT(clusters_classified, "radial view",                                                       \
        "radial-view clusters classified (lazily: only where a kept pair needed it)")             \
  COUNT(clusters_certified, "radial view", "radial-view clusters skipped whole")                 \
  COUNT(radial_positive, "radial view",                                                           \
        "triangles (real + ghost) of the classified clusters facing their observer")              \
  COUNT(radial_negative, "radial view", "triangles of the classified clusters facing away")      \
  COUNT(radial_undetermined, "radial view",                                                       \
        "triangles of the classified clusters facing neither way over the whole step")            \
  COUNT(candidate_triangle_pairs, "traversal", "candidate triangle pairs (CTPs) emitted")        \
  COUNT(triangle_pairs_separated, "low level",                                                    \
        "CTPs the triangle filter dropped whole (one face on one side of the other's plane)")     \
  COUNT(triangle_pairs_apart, "low level",                                                        \
        "CTPs the separating-direction filter dropped (kept apart along one fixed direction)")    \
  COUNT(isolated_vf_pairs, "isolated set", "vertex-face pairs of the isolated set")              \
  COUNT(isolated_ee_pairs, "isolated set", "edge-edge pairs of the isolated set")                \
  COUNT(vf_generated, "low level", "vertex-face pairs generated from the CTPs + isolated set")   \
  COUNT(ee_generated, "low level", "edge-edge pairs generated from the CTPs + isolated set")     \
  COUNT(vf_after_boxes, "low level", "vertex-face pairs that survived the primitive boxes")      \
  COUNT(ee_after_boxes, "low level", "edge-edge pairs that survived the primitive boxes")        \
  COUNT(vf_after_filter, "low level", "vertex-face pairs that survived the DNF filter")          \
  COUNT(ee_after_filter, "low level", "edge-edge pairs that survived the DNF filter")            \
  COUNT(vf_after_projection, "low level",                                                         \
        "vertex-face pairs that survived the projection filter")                                  \
  COUNT(ee_after_projection, "low level", "edge-edge pairs that survived the projection filter") \
  COUNT(vf_tested, "exact CCD", "vertex-face pairs sent to the exact CCD")                       \
  COUNT(ee_tested, "exact CCD", "edge-edge pairs sent to the exact CCD")                         \
  COUNT(vf_colliding, "exact CCD", "vertex-face collisions found")                               \
  COUNT(ee_colliding, "exact CCD", "edge-edge collisions found")                                 \
  COUNT(ccd_exact_fallbacks, "exact CCD", "queries the exact path decided")                      \
  TIME(refit_ms, "refit", "refitting the BVH's boxes and direction masks")                       \
  TIME(traversal_ms, "traversal", "the BVH traversal (high-level culling)")                      \
  TIME(radial_view_ms, "radial view", "radial-view culling")                                     \
  TIME(pair_generation_ms, "low level", "generating and culling the primitive pairs")            \
  TIME(ccd_ms, "exact CCD", "the exact CCD and gathering the collisions")                        \
  TIME(total_ms, "step", "the whole step, the input check included")
// clang-format on

/// Per-stage statistics of one detection step (counts are exact, times in milliseconds).
/// The members are TAILOR_DETECTION_STATS above (docs/settings.md lists them).
struct DetectionStats {
#define TAILOR_DECLARE_COUNT(name, ...) std::int64_t name = 0;
#define TAILOR_DECLARE_TIME(name, ...) double name = 0;
  TAILOR_DETECTION_STATS(TAILOR_DECLARE_COUNT, TAILOR_DECLARE_TIME)
#undef TAILOR_DECLARE_COUNT
#undef TAILOR_DECLARE_TIME

  /// Adds another step's counts and times (for means over many steps).
  DetectionStats& operator+=(const DetectionStats& other);
};

/// A pointer to one member of DetectionStats: a count or a time.
using DetectionStatsMember = std::variant<std::int64_t DetectionStats::*, double DetectionStats::*>;

/// One field of DetectionStats, as the JSON output and the docs read it.
struct DetectionStatField {
  std::string_view name;        ///< the member's name (C++, JSON key, Python dict key)
  DetectionStatsMember member;  ///< the member itself
  std::string_view stage;       ///< the stage that fills it
  std::string_view help;        ///< one line
  /// True for a time in milliseconds (a double), false for a count.
  bool is_time() const { return std::holds_alternative<double DetectionStats::*>(member); }
};

/// Every field of DetectionStats, in declaration order.
inline constexpr std::array kDetectionStatFields{
#define TAILOR_STAT_ROW(name, stage, help) \
  DetectionStatField{#name, &DetectionStats::name, stage, help},
    TAILOR_DETECTION_STATS(TAILOR_STAT_ROW, TAILOR_STAT_ROW)
#undef TAILOR_STAT_ROW
};

/// JSON object with every field of `stats`.
void to_json(nlohmann::json& json, const DetectionStats& stats);

}  // namespace tailor
