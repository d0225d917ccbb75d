/// @file
/// `tailor.check_sequence`: the sequence check of `tailor check` (tailor::SequenceChecker on
/// the files resolve_frame_sources finds) as one call returning plain dicts; what
/// `tailor.batch` runs in every task.

#include <pybind11/stl.h>
#include <tbb/global_control.h>

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "json_objects.hpp"
#include "tailor/detection/sequence_check.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/io/frame_sources.hpp"

namespace tailor::python {
namespace {

/// What `tailor.check_sequence` is asked to do (besides the frames).
struct CheckRequest {
  SequenceCheckOptions options;
  bool per_step = false;
};

nlohmann::json optional_json(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

/// One step as the small record kept per step (the collisions themselves are dropped, so a
/// long sequence's rows stay small).
nlohmann::json step_record(const StepCheck& step) {
  return {{"step", step.step},
          {"vf_collisions", step.vf_collisions()},
          {"ee_collisions", step.ee_collisions()},
          {"earliest_toi", optional_json(step.earliest_toi())},
          {"end_frame", step.end.frame},
          {"end_file", step.end.file.string()},
          {"end_checked", step.end.checked},
          {"end_intersections", step.end.intersections.total()},
          {"detect_ms", step.detect_ms},
          {"check_ms", step.end.check_ms},
          {"read_wait_ms", step.read_wait_ms},
          {"total_ms", step.total_ms}};
}

nlohmann::json summary_json(const SequenceChecker& checker, const FrameSources& sources) {
  const SequenceSummary& s = checker.summary();
  return {{"frames", s.frames},
          {"first_frame", checker.first_frame()},
          {"steps", s.steps},
          {"steps_with_contacts", s.steps_with_contacts},
          {"first_contact_step", s.first_contact_step},
          {"vf_collisions", s.vf_collisions},
          {"ee_collisions", s.ee_collisions},
          {"earliest_toi", optional_json(s.earliest_toi)},
          {"earliest_toi_step", s.earliest_toi_step},
          {"frames_checked", checker.first_frame_check().checked},
          {"frames_with_intersections", s.frames_with_intersections},
          {"first_intersecting_frame", s.first_intersecting_frame},
          {"intersecting_frames", s.intersecting_frames},
          {"vertices", checker.mesh().num_vertices()},
          {"faces", checker.mesh().num_faces()},
          {"frames_pattern", sources.frames_pattern},
          {"obstacle_pattern", sources.obstacle_pattern},
          {"obstacle_frames", sources.obstacle.size()},
          {"setup_ms", s.setup_ms},
          {"steps_ms", s.steps_ms},
          {"detect_ms", s.detect_ms},
          {"check_ms", s.check_ms},
          {"read_wait_ms", s.read_wait_ms}};
}

/// Runs the whole check without the GIL; the result as JSON (converted under the GIL).
nlohmann::json run_check(const std::vector<std::string>& frames, const std::string& obstacle,
                         const CheckRequest& request) {
  const FrameSources sources = resolve_frame_sources(frames, obstacle);
  std::optional<FrameSequence> obstacle_frames;
  if (!sources.obstacle.empty()) obstacle_frames.emplace(sources.obstacle);
  SequenceChecker checker(FrameSequence(sources.frames), std::move(obstacle_frames),
                          request.options);
  nlohmann::json steps = nlohmann::json::array();
  while (std::optional<StepCheck> step = checker.next_step()) {
    if (request.per_step) steps.push_back(step_record(*step));
  }
  nlohmann::json result = summary_json(checker, sources);
  if (request.per_step) result["step_rows"] = std::move(steps);
  return result;
}

std::vector<std::string> frame_arguments(py::handle frames) {
  if (py::isinstance<py::str>(frames) || py::hasattr(frames, "__fspath__")) {
    return {py::str(py::module_::import("os").attr("fspath")(frames)).cast<std::string>()};
  }
  std::vector<std::string> out;
  for (py::handle item : frames) {
    out.push_back(py::str(py::module_::import("os").attr("fspath")(item)).cast<std::string>());
  }
  if (out.empty()) throw InputError("check_sequence: no frames given");
  return out;
}

}  // namespace

void bind_sequence(py::module_& m) {
  m.def(
      "check_sequence",
      [](py::handle frames, py::handle obstacle, py::handle method, int threads, Index first_frame,
         Index last_frame, bool check_frames, int read_ahead, std::size_t max_pairs,
         bool per_step) {
        const std::vector<std::string> arguments = frame_arguments(frames);
        const std::string obstacle_argument =
            obstacle.is_none() ? std::string() : frame_arguments(obstacle).front();
        CheckRequest request;
        request.options.detection = detection_config(method, threads);
        request.options.first_frame = first_frame;
        request.options.last_frame = last_frame;
        request.options.check_frames = check_frames;
        request.options.read_ahead = read_ahead;
        request.options.max_pairs = max_pairs;
        request.per_step = per_step;
        nlohmann::json result;
        {
          py::gil_scoped_release release;
          // As `tailor check --threads N`: the limit holds for the whole check.
          std::optional<tbb::global_control> limit;
          if (threads > 0) {
            limit.emplace(tbb::global_control::max_allowed_parallelism,
                          static_cast<std::size_t>(threads));
          }
          result = run_check(arguments, obstacle_argument, request);
        }
        return to_python(result);
      },
      py::arg("frames"), py::arg("obstacle") = py::none(), py::kw_only(),
      py::arg("method") = "paper", py::arg("threads") = 0, py::arg("first_frame") = 0,
      py::arg("last_frame") = -1, py::arg("check_frames") = true,
      py::arg("read_ahead") = SequenceCheckOptions::kAutoReadAhead,
      py::arg("max_pairs") = std::size_t{10}, py::arg("per_step") = false,
      "The check `tailor check FRAMES... [--obstacle O]` runs, as one call: `frames` is a "
      "folder, a glob, a printf pattern or a list of frame files (a folder written by `tailor "
      "simulate` takes arm_*.obj as the obstacle); `obstacle` one frame or one per frame. "
      "Returns the summary as a dict (frames, steps, vf_collisions, ee_collisions, "
      "earliest_toi, frames_with_intersections, first_intersecting_frame, times in ms, ...), "
      "with `step_rows` (one dict per step) when `per_step`. Frames are read ahead within "
      "`read_ahead` (-1: 64 MiB), so memory does not grow with the sequence. Raises "
      "InputError on a bad or missing frame. The GIL is released while it runs.");
}

}  // namespace tailor::python
