#pragma once
/// @file
/// What `tailor view` shows, opened from a `tailor simulate` output folder or from the
/// JSON of `tailor detect` with its two meshes. Frames are read one at a time, so long
/// runs never sit in memory; every read checks its input and throws InputError naming
/// the file.

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "tailor/detection/detection_config.hpp"
#include "tailor/geometry/types.hpp"
#include "view/frame_contacts.hpp"

namespace tailor::cli {

/// One frame: positions, and the contacts of the step that ended at it (if known).
struct ViewFrame {
  Positions cloth;
  Positions arm;  ///< no rows when there is no arm
  std::optional<FrameContacts> contacts;
};

/// A sequence of frames of one cloth (and optionally one arm) with its overlays.
struct ViewInput {
  std::string kind;   ///< "simulation" or "detection"
  std::string title;  ///< what the page names as its source
  int num_frames = 0;
  Index cloth_vertices = 0;
  FaceArray cloth_faces;
  Index arm_vertices = 0;  ///< 0 without an arm
  FaceArray arm_faces;
  std::vector<Index> cluster_of_face;  ///< radial-view cluster per cloth face; empty if unknown
  nlohmann::json stats;                ///< per-frame series (see step_stats.hpp), or null
  /// Reads frame `k` (0 <= k < num_frames), checked against the first frame.
  std::function<ViewFrame(int)> load_frame;
};

/// Opens the output of `tailor simulate --out DIR`: cloth_NNNN.obj from frame 0 on (and
/// arm_NNNN.obj for the same frames if arm_0000.obj exists), steps.jsonl, summary.json,
/// contacts_NNNN.json and clusters.json where present. Throws InputError naming `dir` if
/// it is not a folder or holds no cloth_0000.obj, and naming the file for any file that
/// is malformed or does not match frame 0 (vertex count, faces).
ViewInput open_simulation_output(const std::filesystem::path& dir);

/// Opens one detected step: `json` written by `tailor detect T0 T1 --json` and its meshes
/// `t0`, `t1` (frames 0 and 1; the collisions belong to frame 1). With `candidates`, runs
/// that detection configuration once more to find the faces in candidate triangle pairs
/// (the JSON does not hold them). Throws InputError naming the file on malformed input,
/// meshes of different topology, or ids out of range.
ViewInput open_detection_output(const std::filesystem::path& json, const std::filesystem::path& t0,
                                const std::filesystem::path& t1,
                                std::optional<DetectionConfig> candidates);

}  // namespace tailor::cli
