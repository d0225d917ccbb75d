#pragma once
/// @file
/// The per-frame statistics panel of `tailor view`: the records of `steps.jsonl` (one per
/// substep) summed per frame, or the single step of `tailor detect --json`.

#include <filesystem>
#include <nlohmann/json.hpp>

namespace tailor::cli {

/// Reads `steps.jsonl` of a run with `num_frames` frames (frame 0 the initial state) and
/// sums every numeric field of the records of each frame; nested objects are flattened
/// with dots ("detection.vf_tested", "ms.step"). Returns `{"series": {name: [value or
/// null per frame]}}` (null where no record names the frame). The bookkeeping fields
/// frame, substep and time, and solver.residual (not additive), are left out. Throws
/// InputError naming the file and line on a line that is not a JSON object with an
/// integer "frame" in [1, num_frames).
nlohmann::json read_frame_stats(const std::filesystem::path& path, int num_frames);

/// The same shape for one detected step (the "stats" object of `tailor detect --json`)
/// shown at frame 1 of 2, under "detection.<field>" like the simulation's records.
nlohmann::json single_step_stats(const nlohmann::json& detection_stats);

}  // namespace tailor::cli
