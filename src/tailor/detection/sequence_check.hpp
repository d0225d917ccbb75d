#pragma once
/// @file
/// Checking a whole frame sequence (e.g. a simulator's output): the self-collisions of every
/// step k → k+1 with one SelfCollisionDetector built once, and the exact static intersection
/// check of every frame (against an obstacle sequence too), frames read ahead on a second
/// thread. Plain structs out, pulled one step at a time or pushed to a callback.

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "tailor/detection/detection_config.hpp"
#include "tailor/detection/intersection_check.hpp"
#include "tailor/detection/self_collision_detector.hpp"
#include "tailor/io/frame_sequence.hpp"

namespace tailor {

/// What a SequenceChecker runs.
struct SequenceCheckOptions {
  /// Culling stages and threads of the detector.
  DetectionConfig detection = DetectionConfig::preset("paper");
  /// Radial-view observers: rings of cloth vertex ids (see SelfCollisionDetector).
  std::vector<std::vector<Index>> section_loops;
  Index first_frame = 0;       ///< first frame checked (position in the sequence, 0-based)
  Index last_frame = -1;       ///< last frame checked, inclusive; -1: the sequence's last
  bool check_frames = true;    ///< run the exact static intersection check on every frame
  std::size_t max_pairs = 10;  ///< intersecting face pairs listed per frame
  /// Frames read ahead on a second thread; 0: read in next_step. kAutoReadAhead: as many
  /// as fit in kAutoReadAheadBytes, 2 to kMaxAutoReadAhead (a deep queue lets the reader
  /// catch up whenever it gets a core, on a machine busy with other work).
  int read_ahead = kAutoReadAhead;

  /// read_ahead: choose the depth by frame size.
  static constexpr int kAutoReadAhead = -1;
  /// Memory the automatic read ahead may fill with frames.
  static constexpr std::size_t kAutoReadAheadBytes = std::size_t{64} << 20;
  /// Deepest automatic read ahead (64 MiB hold many frames of a small mesh).
  static constexpr int kMaxAutoReadAhead = 64;
};

/// The static check of one frame.
struct FrameCheck {
  Index frame = -1;                  ///< position in the sequence
  std::filesystem::path file;        ///< the frame's file
  bool checked = false;              ///< false when SequenceCheckOptions::check_frames is off
  IntersectionReport intersections;  ///< cloth-cloth and cloth-obstacle (if checked)
  double check_ms = 0;               ///< time of the static check

  /// True unless the check ran and found an intersection.
  bool intersection_free() const { return !checked || intersections.intersection_free(); }
};

/// One step k → k+1: its collisions and the static check of both frames.
struct StepCheck {
  Index step = -1;  ///< k, the position of the step's first frame
  ///@{
  /// Frames k and k+1 (start repeats the previous step's end).
  FrameCheck start, end;
  ///@}
  CollisionSet collisions;  ///< every VF and EE collision of the step (exact)
  DetectionStats stats;     ///< the detector's per-stage counts and times
  double read_wait_ms = 0;  ///< time spent waiting for frame k+1 (reading not overlapped)
  double detect_ms = 0;     ///< wall time of the detection
  double total_ms = 0;      ///< wall time of the whole step (wait, detection, static check)

  /// Number of vertex-face collisions of the step.
  std::int64_t vf_collisions() const {
    return static_cast<std::int64_t>(collisions.vertex_face.size());
  }
  /// Number of edge-edge collisions of the step.
  std::int64_t ee_collisions() const {
    return static_cast<std::int64_t>(collisions.edge_edge.size());
  }
  /// True when something touches during the step.
  bool has_contacts() const { return collisions.size() > 0; }
  /// The earliest time of impact in [0, 1] (conservative: never later than the true one);
  /// none without collisions.
  std::optional<double> earliest_toi() const;
};

/// Totals over the frames and steps checked so far.
struct SequenceSummary {
  Index frames = 0;                        ///< frames read (and checked, if on)
  Index steps = 0;                         ///< steps detected
  Index steps_with_contacts = 0;           ///< steps with at least one collision
  Index first_contact_step = -1;           ///< first such step (-1: none)
  std::int64_t vf_collisions = 0;          ///< over all steps
  std::int64_t ee_collisions = 0;          ///< over all steps
  std::optional<double> earliest_toi;      ///< earliest over all steps
  Index earliest_toi_step = -1;            ///< the step it occurred in
  Index frames_with_intersections = 0;     ///< frames the static check found intersecting
  Index first_intersecting_frame = -1;     ///< -1: none
  std::vector<Index> intersecting_frames;  ///< all of them, in order
  double setup_ms = 0;       ///< first frame read, detector built, first frame checked
  double steps_ms = 0;       ///< sum of StepCheck::total_ms
  double detect_ms = 0;      ///< sum of StepCheck::detect_ms
  double check_ms = 0;       ///< static checks of every frame
  double read_wait_ms = 0;   ///< sum of StepCheck::read_wait_ms
  DetectionStats detection;  ///< per-stage counts and times summed over the steps

  /// Mean wall time of a step (0 before the first).
  double ms_per_step() const { return steps > 0 ? steps_ms / steps : 0.0; }
  /// True when no checked frame intersects.
  bool intersection_free() const { return frames_with_intersections == 0; }
};

/// Checks frames `first..last` of a sequence step by step. Owns its sequences; reads them
/// ahead on reader threads (FramePrefetcher), builds one SelfCollisionDetector on the first
/// frame and reuses it for every step. Errors of a frame (unreadable, or vertex count or
/// faces unlike the first frame) surface as an InputError naming the file, from the
/// next_step() call that reaches that frame; every earlier step has been returned by then,
/// and every later call throws the same error (the checker cannot go on past it).
class SequenceChecker {
 public:
  /// Reads and checks the first frame, builds the detector. `obstacle` (optional) is either
  /// one frame (a still obstacle) or as many frames as `frames`, frame i going with frame i.
  /// Throws InputError on a range outside the sequence, a mismatched obstacle frame count,
  /// an invalid mesh or observers, or an unreadable first frame.
  explicit SequenceChecker(FrameSequence frames, std::optional<FrameSequence> obstacle = {},
                           SequenceCheckOptions options = {});
  ~SequenceChecker();
  /// Moves the checker; the moved-from one may only be destroyed or assigned to.
  SequenceChecker(SequenceChecker&&) noexcept;
  /// Move assignment (as the move constructor).
  SequenceChecker& operator=(SequenceChecker&&) noexcept;

  /// The next step, or std::nullopt after the last one.
  std::optional<StepCheck> next_step();

  /// The static check of the first frame (also the `start` of the first step).
  const FrameCheck& first_frame_check() const;
  /// Totals so far.
  const SequenceSummary& summary() const;
  /// First frame of the range.
  Index first_frame() const;
  /// Last frame of the range (inclusive).
  Index last_frame() const;
  /// Number of steps in the range: last_frame() - first_frame().
  Index num_steps() const;
  /// The checked sequence.
  const FrameSequence& frames() const;
  /// The cloth's connectivity (the faces of the first frame).
  const TriangleMesh& mesh() const;
  /// The obstacle sequence, or nullptr.
  const FrameSequence* obstacle() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> m_impl;
};

/// Runs a SequenceChecker to the end, calling `on_step` after each step; `on_step` returns
/// false to stop early. Returns the summary of what was checked.
SequenceSummary check_sequence(FrameSequence frames, std::optional<FrameSequence> obstacle,
                               SequenceCheckOptions options,
                               const std::function<bool(const StepCheck&)>& on_step);

}  // namespace tailor
