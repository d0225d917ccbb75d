#pragma once
/// @file
/// Which culling stages a SelfCollisionDetector runs; presets are the paper's Table 1 rows.
///
/// Every setting is declared once, in TAILOR_DETECTION_SETTINGS below: its name, type,
/// default, range, command-line spelling, effect on the result and one line of help. The
/// struct's members, kDetectionSettings (what the CLI options, the Python binding, the JSON
/// output and docs/settings.md are made from) all expand that list; adding a setting is one
/// line there (docs/design.md, "Adding a setting").

#include <array>
#include <limits>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace tailor {

/// What a setting can change.
enum class SettingEffect {
  /// Only the work: every value reports exactly the brute-force collisions.
  work_only,
  /// Only what the result holds beside the collisions (statistics, candidate pairs); the
  /// collisions stay exact.
  output_only,
  /// Off, it can miss collisions (kept to measure what it costs; no preset that uses what
  /// it guards turns it off).
  unsound_when_off,
  /// It changes which pairs count as colliding (e.g. a thickness): the result is exact for
  /// its value, and brute force must be given the same value to compare.
  defines_result,
};

/// Upper bound of a setting without one.
inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

/// Every setting of DetectionConfig, once, in declaration order:
///   SWITCH(name, default, cli, effect, help)                  a bool: --cli / --no-cli
///   NUMBER(type, name, default, min, max, cli, effect, help)  an int or double: --cli VALUE
/// `cli` is the command-line spelling ("" when the CLI sets it itself); `effect` a
/// SettingEffect; `help` one line, without a final period. The defaults are the `paper` preset.
// clang-format off
#define TAILOR_DETECTION_SETTINGS(SWITCH, NUMBER)                                                 \
  SWITCH(normal_cones, true, "cones", work_only,                                                  \
         "continuous normal-cone culling: skip the self-test of a BVH node whose normal cone "    \
         "(direction masks) and contour certify it")                                              \
  SWITCH(contour_test, true, "contour", unsound_when_off,                                         \
         "the contour test that makes normal-cone culling sound; off, the cone alone skips a "    \
         "node and collisions can be missed (for comparison only)")                               \
  SWITCH(diagonal_bounds, true, "diagonal-bounds", work_only,                                     \
         "bounds along the four diagonals beside each BVH node's box: the traversal skips node "     \
         "pairs kept apart along one of them at both ends of the step (bvh/diagonal_bounds.hpp)") \
  SWITCH(adjacency_culling, true, "adjacency", work_only,                                         \
         "adjacency culling: no triangle pairs sharing a vertex (their pairs come from the "      \
         "isolated set)")                                                                         \
  SWITCH(triangle_filter, true, "triangle-filter", work_only,                                     \
         "triangle filter: drop candidate triangle pairs (and their vertex-face and edge-edge "  \
         "pairs) that a moving triangle plane separates (candidates/triangle_plane_sides.hpp)")   \
  SWITCH(direction_filter, true, "direction-filter", work_only,                                   \
         "separating-direction filter: drop candidate triangle pairs that one fixed direction "   \
         "keeps apart at both ends of the step (candidates/step_separating_direction.hpp)")       \
  SWITCH(feature_assignment, true, "assignment", work_only,                                       \
         "feature assignment: each vertex and edge tested through one representative triangle "   \
         "(Curtis et al. 2008)")                                                                  \
  SWITCH(primitive_boxes, true, "primitive-boxes", work_only,                                     \
         "bounding boxes of the vertex-face and edge-edge pairs at both ends of the step "        \
         "(bvh/step_boxes.hpp)")                                                                  \
  SWITCH(coplanarity_filter, true, "filter", work_only,                                           \
         "non-coplanarity (DNF) filter: drop pairs that can never become coplanar")               \
  SWITCH(projection_filter, true, "projection", work_only,                                        \
         "projection filter: drop pairs whose projection along one direction cannot touch "       \
         "(candidates/projection_filter.hpp)")                                                    \
  SWITCH(radial_view, true, "radial", work_only,                                                  \
         "radial-view culling, where observers (section loops) are given")                        \
  NUMBER(double, thickness, 0.0, 0, 1e300, "thickness", defines_result,                           \
         "collisions with a thickness: report each pair that comes within this distance during "  \
         "the step, at the earliest such time (0: touching); above 0 only boxes at both ends of " \
         "the step grown by half of it and thickness_filter cull, the other stages are off "      \
         "(ccd/thickness_ccd.hpp)")                                                               \
  SWITCH(thickness_filter, true, "thickness-filter", work_only,                                   \
         "with a thickness: drop the pairs their own normal, or the direction between them, "    \
         "keeps more than it apart for the whole step before the CCD "                            \
         "(candidates/thickness_pair_filter.hpp)")                                                \
  NUMBER(int, threads, 0, 0, kUnbounded, "threads", work_only,                                    \
         "worker threads (0: all hardware threads)")                                              \
  SWITCH(classify_every_cluster, false, "classify-every-cluster", output_only,                    \
         "radial view: classify every cluster each step, as the paper does, to fill "             \
         "radial_positive / negative / undetermined (the same pairs are culled)")                 \
  SWITCH(keep_candidate_pairs, false, "", output_only,                                            \
         "copy the step's candidate triangle pairs into DetectionResult (pictures, viewers; "     \
         "memory at scale; the CLI sets it where it writes pairs)")
// clang-format on

/// Switches for every culling stage (the members are TAILOR_DETECTION_SETTINGS above;
/// docs/settings.md lists them). Each switch changes only the work, except `contour_test`:
/// off (with `normal_cones` on) it can miss collisions. A default-constructed config is the
/// `paper` preset.
struct DetectionConfig {
#define TAILOR_DECLARE_SWITCH(name, value, ...) bool name = value;
#define TAILOR_DECLARE_NUMBER(type, name, value, ...) type name = value;
  TAILOR_DETECTION_SETTINGS(TAILOR_DECLARE_SWITCH, TAILOR_DECLARE_NUMBER)
#undef TAILOR_DECLARE_SWITCH
#undef TAILOR_DECLARE_NUMBER

  /// `basic`, `curtis`, `tang` or `paper`; throws InputError naming the bad name.
  static DetectionConfig preset(std::string_view name);
  /// Names accepted by preset().
  static std::vector<std::string> preset_names();
};

/// A pointer to one member of DetectionConfig, of any setting type.
using DetectionConfigMember =
    std::variant<bool DetectionConfig::*, int DetectionConfig::*, double DetectionConfig::*>;

/// One setting of DetectionConfig, as the surfaces (CLI, Python, JSON, docs) read it. The
/// default is `DetectionConfig{}.*member`.
struct DetectionSetting {
  std::string_view name;         ///< the member's name (C++, Python, JSON key)
  DetectionConfigMember member;  ///< the member itself
  std::string_view cli;          ///< `--cli`/`--no-cli` or `--cli VALUE`; empty: not on the CLI
  ///@{
  /// Accepted range, inclusive (a switch: 0 and 1; max may be kUnbounded).
  double min = 0, max = 1;
  ///@}
  SettingEffect effect = SettingEffect::work_only;  ///< what it can change
  std::string_view help;                            ///< one line
};

/// Every setting of DetectionConfig, in declaration order.
inline constexpr std::array kDetectionSettings{
#define TAILOR_SWITCH_ROW(name, value, cli, effect, help) \
  DetectionSetting{#name, &DetectionConfig::name, cli, 0, 1, SettingEffect::effect, help},
#define TAILOR_NUMBER_ROW(type, name, value, min, max, cli, effect, help) \
  DetectionSetting{#name, &DetectionConfig::name, cli, min, max, SettingEffect::effect, help},
    TAILOR_DETECTION_SETTINGS(TAILOR_SWITCH_ROW, TAILOR_NUMBER_ROW)
#undef TAILOR_SWITCH_ROW
#undef TAILOR_NUMBER_ROW
};

/// The effect's name for people: "work only", "output only", "unsound when off", "defines
/// the result".
std::string_view to_string(SettingEffect effect);

/// `setting`'s value in `config` as text: `true`/`false` or the number.
std::string setting_value(const DetectionConfig& config, const DetectionSetting& setting);

/// JSON object with every setting of `config` (keys: the setting names).
void to_json(nlohmann::json& json, const DetectionConfig& config);

}  // namespace tailor
