/// @file
/// The step loop of sequence checking: prefetched frames, one detector, per-frame checks.

#include "tailor/detection/sequence_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <exception>

#include "tailor/geometry/error.hpp"
#include "tailor/geometry/stopwatch.hpp"
#include "tailor/io/frame_prefetch.hpp"

namespace tailor {
namespace {

Index resolve_last_frame(const FrameSequence& frames, const SequenceCheckOptions& options) {
  const Index last = options.last_frame < 0 ? frames.num_frames() - 1 : options.last_frame;
  if (options.first_frame < 0 || options.first_frame > last || last >= frames.num_frames()) {
    throw InputError(fmt::format(
        "frames {} to {} are not within the sequence {} .. {} ({} frames, numbered from 0)",
        options.first_frame, last, frames.path(0).string(),
        frames.path(frames.num_frames() - 1).string(), frames.num_frames()));
  }
  return last;
}

/// The read ahead of one sequence's reader: `options.read_ahead`, or the automatic depth
/// for frames of `num_vertices` vertices.
int resolve_read_ahead(const SequenceCheckOptions& options, Index num_vertices) {
  if (options.read_ahead != SequenceCheckOptions::kAutoReadAhead) return options.read_ahead;
  const std::size_t frame_bytes = sizeof(double) * 3 * static_cast<std::size_t>(num_vertices) + 1;
  const std::size_t fit = SequenceCheckOptions::kAutoReadAheadBytes / frame_bytes;
  const std::size_t deepest = SequenceCheckOptions::kMaxAutoReadAhead;
  return static_cast<int>(std::clamp<std::size_t>(fit, 2, deepest));
}

void check_obstacle_count(const FrameSequence& frames, const FrameSequence& obstacle) {
  if (obstacle.num_frames() != 1 && obstacle.num_frames() != frames.num_frames()) {
    throw InputError(
        fmt::format("the obstacle has {} frames ({} ..) but the sequence has {} ({} ..): give one "
                    "obstacle frame, or one per frame",
                    obstacle.num_frames(), obstacle.path(0).string(), frames.num_frames(),
                    frames.path(0).string()));
  }
}

}  // namespace

std::optional<double> StepCheck::earliest_toi() const {
  std::optional<double> earliest;
  const auto consider = [&](double toi) {
    if (!earliest || toi < *earliest) earliest = toi;
  };
  for (const auto& c : collisions.vertex_face) consider(c.toi);
  for (const auto& c : collisions.edge_edge) consider(c.toi);
  return earliest;
}

struct SequenceChecker::Impl {
  FrameSequence frames;
  std::optional<FrameSequence> obstacle;
  SequenceCheckOptions options;
  Index last;
  TriangleMesh mesh;
  std::optional<TriangleMesh> obstacle_mesh;
  FramePrefetcher cloth_reader;
  std::optional<FramePrefetcher> obstacle_reader;  // none: still obstacle, or no frame check
  Positions x;                                     // cloth at the current frame
  Positions y;                                     // obstacle at the current frame (if read)
  std::optional<SelfCollisionDetector> detector;
  FrameCheck first;          // static check of the first frame
  FrameCheck current;        // static check of the current frame
  std::exception_ptr error;  // a step's error: the checker cannot go on past it
  SequenceSummary summary;

  Impl(FrameSequence frames_in, std::optional<FrameSequence> obstacle_in,
       SequenceCheckOptions options_in)
      : frames(std::move(frames_in)),
        obstacle(std::move(obstacle_in)),
        options(std::move(options_in)),
        last(validate(frames, obstacle, options)),
        mesh(frames.num_vertices(), frames.faces()),
        cloth_reader(frames, options.first_frame, last,
                     resolve_read_ahead(options, frames.num_vertices())) {
    const auto start = SteadyClock::now();
    if (obstacle) obstacle_mesh.emplace(obstacle->num_vertices(), obstacle->faces());
    // Only the static check looks at the obstacle: without it, its frames are not read.
    if (obstacle && options.check_frames) {
      if (obstacle->num_frames() == 1) {
        y = obstacle->load(0);
      } else {
        obstacle_reader.emplace(*obstacle, options.first_frame, last,
                                resolve_read_ahead(options, obstacle->num_vertices()));
        y = *obstacle_reader->next();
      }
    }
    x = *cloth_reader.next();
    detector.emplace(mesh, x, options.detection, options.section_loops);
    first = check_frame(options.first_frame, x, y);
    current = first;
    summary.setup_ms = milliseconds_since(start);
  }

  static Index validate(const FrameSequence& frames, const std::optional<FrameSequence>& obstacle,
                        const SequenceCheckOptions& options) {
    if (obstacle) check_obstacle_count(frames, *obstacle);
    return resolve_last_frame(frames, options);
  }

  double wait_ms() const {
    return cloth_reader.wait_ms() + (obstacle_reader ? obstacle_reader->wait_ms() : 0.0);
  }

  FrameCheck check_frame(Index frame, const Positions& cloth, const Positions& obstacle_at) {
    FrameCheck check;
    check.frame = frame;
    check.file = frames.path(frame);
    ++summary.frames;
    if (!options.check_frames) return check;
    const auto start = SteadyClock::now();
    check.intersections =
        check_intersections(mesh, cloth, obstacle_mesh ? &*obstacle_mesh : nullptr,
                            obstacle_mesh ? &obstacle_at : nullptr, options.max_pairs);
    check.checked = true;
    check.check_ms = milliseconds_since(start);
    summary.check_ms += check.check_ms;
    if (!check.intersections.intersection_free()) {
      ++summary.frames_with_intersections;
      if (summary.first_intersecting_frame < 0) summary.first_intersecting_frame = frame;
      summary.intersecting_frames.push_back(frame);
    }
    return check;
  }

  std::optional<StepCheck> next_step() {
    if (error) std::rethrow_exception(error);
    try {
      return advance();
    } catch (...) {
      error = std::current_exception();
      throw;
    }
  }

  std::optional<StepCheck> advance() {
    const Index k = cloth_reader.next_index() - 1;  // the current frame
    if (k >= last) return std::nullopt;
    const auto start = SteadyClock::now();
    const double wait_before = wait_ms();
    Positions x1 = *cloth_reader.next();                 // k < last: present
    std::optional<Positions> y1;                         // a still obstacle stays in y
    if (obstacle_reader) y1 = *obstacle_reader->next();  // same range as the cloth
    StepCheck step;
    step.step = k;
    step.read_wait_ms = wait_ms() - wait_before;
    const auto detect_start = SteadyClock::now();
    DetectionResult result = detector->detect(x, x1);
    step.detect_ms = milliseconds_since(detect_start);
    step.collisions = std::move(result.collisions);
    step.stats = result.stats;
    step.start = std::move(current);
    current = check_frame(k + 1, x1, y1 ? *y1 : y);
    step.end = current;
    x = std::move(x1);
    if (y1) y = std::move(*y1);
    step.total_ms = milliseconds_since(start);
    add_to_summary(step);
    return step;
  }

  void add_to_summary(const StepCheck& step) {
    ++summary.steps;
    summary.steps_ms += step.total_ms;
    summary.detect_ms += step.detect_ms;
    summary.read_wait_ms += step.read_wait_ms;
    summary.detection += step.stats;
    summary.vf_collisions += step.vf_collisions();
    summary.ee_collisions += step.ee_collisions();
    if (!step.has_contacts()) return;
    ++summary.steps_with_contacts;
    if (summary.first_contact_step < 0) summary.first_contact_step = step.step;
    const double toi = *step.earliest_toi();
    if (!summary.earliest_toi || toi < *summary.earliest_toi) {
      summary.earliest_toi = toi;
      summary.earliest_toi_step = step.step;
    }
  }
};

SequenceChecker::SequenceChecker(FrameSequence frames, std::optional<FrameSequence> obstacle,
                                 SequenceCheckOptions options)
    : m_impl(std::make_unique<Impl>(std::move(frames), std::move(obstacle), std::move(options))) {}
SequenceChecker::~SequenceChecker() = default;
SequenceChecker::SequenceChecker(SequenceChecker&&) noexcept = default;
SequenceChecker& SequenceChecker::operator=(SequenceChecker&&) noexcept = default;

std::optional<StepCheck> SequenceChecker::next_step() {
  return m_impl->next_step();
}
const FrameCheck& SequenceChecker::first_frame_check() const {
  return m_impl->first;
}
const SequenceSummary& SequenceChecker::summary() const {
  return m_impl->summary;
}
Index SequenceChecker::first_frame() const {
  return m_impl->options.first_frame;
}
Index SequenceChecker::last_frame() const {
  return m_impl->last;
}
Index SequenceChecker::num_steps() const {
  return m_impl->last - m_impl->options.first_frame;
}
const FrameSequence& SequenceChecker::frames() const {
  return m_impl->frames;
}
const TriangleMesh& SequenceChecker::mesh() const {
  return m_impl->mesh;
}
const FrameSequence* SequenceChecker::obstacle() const {
  return m_impl->obstacle ? &*m_impl->obstacle : nullptr;
}

SequenceSummary check_sequence(FrameSequence frames, std::optional<FrameSequence> obstacle,
                               SequenceCheckOptions options,
                               const std::function<bool(const StepCheck&)>& on_step) {
  SequenceChecker checker(std::move(frames), std::move(obstacle), std::move(options));
  while (std::optional<StepCheck> step = checker.next_step()) {
    if (on_step && !on_step(*step)) break;
  }
  return checker.summary();
}

}  // namespace tailor
