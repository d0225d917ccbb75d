/// @file
/// `tailor check FRAMES...`: every step of a frame sequence (self-collisions) and every frame
/// (exact static intersection check, against an obstacle too), with tailor::SequenceChecker.

#include <fcntl.h>
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "command.hpp"
#include "detection_options.hpp"
#include "interrupt.hpp"
#include "progress.hpp"
#include "tailor/detection/sequence_check.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/io/frame_sources.hpp"
#include "tailor/io/observer_loops.hpp"

namespace tailor::cli {
namespace {

struct CheckArgs {
  std::vector<std::string> frames;
  std::string obstacle, json_lines_path, observers_path;
  std::optional<Index> from, to;
  bool no_frame_check = false;
  int read_ahead = SequenceCheckOptions::kAutoReadAhead;
  std::size_t max_pairs = 10;
  DetectionOptions detection;
};

/// One JSON record per line, each written whole with one write(2) as soon as it is ready,
/// so a reader (or a Ctrl-C) never sees a partial record.
class JsonLinesFile {
 public:
  explicit JsonLinesFile(const std::string& path) : m_path(path) {
    m_fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (m_fd < 0) throw InputError(fmt::format("{}: cannot write: {}", path, std::strerror(errno)));
  }
  ~JsonLinesFile() { ::close(m_fd); }
  JsonLinesFile(const JsonLinesFile&) = delete;
  JsonLinesFile& operator=(const JsonLinesFile&) = delete;

  void write(const nlohmann::json& record) {
    const std::string line = record.dump() + "\n";
    std::size_t done = 0;
    while (done < line.size()) {
      const ssize_t n = ::write(m_fd, line.data() + done, line.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        throw InputError(fmt::format("{}: cannot write: {}", m_path, std::strerror(errno)));
      }
      done += static_cast<std::size_t>(n);
    }
  }

 private:
  std::string m_path;
  int m_fd = -1;
};

nlohmann::json frame_json(const FrameCheck& frame) {
  nlohmann::json json = {
      {"frame", frame.frame}, {"file", frame.file.string()}, {"checked", frame.checked}};
  if (!frame.checked) return json;
  const IntersectionReport& r = frame.intersections;
  json["intersection_free"] = r.intersection_free();
  json["self_intersections"] = r.self_intersections;
  json["adjacent_intersections"] = r.adjacent_intersections;
  json["obstacle_intersections"] = r.obstacle_intersections;
  json["degenerate_faces"] = r.degenerate_faces;
  json["undecided_adjacent_pairs"] = r.undecided_adjacent_pairs;
  json["self_pairs"] = r.self_pairs;
  json["obstacle_pairs"] = r.obstacle_pairs;
  json["check_ms"] = frame.check_ms;
  return json;
}

nlohmann::json step_json(const StepCheck& step) {
  const std::optional<double> toi = step.earliest_toi();
  return {{"step", step.step},
          {"start", frame_json(step.start)},
          {"end", frame_json(step.end)},
          {"vf_collisions", step.vf_collisions()},
          {"ee_collisions", step.ee_collisions()},
          {"earliest_toi", toi ? nlohmann::json(*toi) : nlohmann::json(nullptr)},
          {"ms",
           {{"total", step.total_ms},
            {"detect", step.detect_ms},
            {"read_wait", step.read_wait_ms},
            {"check", step.end.check_ms}}},
          {"stats", step.stats}};
}

std::string file_name(const std::filesystem::path& path) {
  return path.filename().string();
}

void print_summary(const SequenceChecker& checker, const FrameSources& sources,
                   const std::string& method, bool interrupted, bool stopped_by_error) {
  const SequenceSummary& s = checker.summary();
  const FrameSequence& frames = checker.frames();
  const auto& row = print_summary_row;
  fmt::print("\ncheck summary\n");
  const Index last_read = checker.first_frame() + s.frames - 1;
  row("frames",
      fmt::format("{} read, {} .. {} ({} .. {}){}", s.frames, checker.first_frame(), last_read,
                  file_name(frames.path(checker.first_frame())), file_name(frames.path(last_read)),
                  interrupted        ? " (interrupted)"
                  : stopped_by_error ? " (stopped at a bad frame)"
                                     : ""));
  row("mesh", fmt::format("{} vertices, {} faces", checker.mesh().num_vertices(),
                          checker.mesh().num_faces()));
  if (const FrameSequence* obstacle = checker.obstacle()) {
    const std::string name =
        obstacle->num_frames() == 1 ? file_name(obstacle->path(0)) : sources.obstacle_pattern;
    row("obstacle", fmt::format("{} ({} frame{}{})", name, obstacle->num_frames(),
                                obstacle->num_frames() == 1 ? "" : "s",
                                sources.obstacle_from_layout ? ", beside the cloth frames" : ""));
  } else {
    row("obstacle", "none");
  }
  row("method", method);
  row("steps", std::to_string(s.steps));
  row("steps with contacts", s.steps_with_contacts == 0
                                 ? std::string("0")
                                 : fmt::format("{} (first: step {} → {})", s.steps_with_contacts,
                                               s.first_contact_step, s.first_contact_step + 1));
  row("collisions VF / EE", fmt::format("{} / {}", s.vf_collisions, s.ee_collisions));
  row("earliest toi", s.earliest_toi ? fmt::format("{:.6g} (step {} → {})", *s.earliest_toi,
                                                   s.earliest_toi_step, s.earliest_toi_step + 1)
                                     : std::string("-"));
  if (!checker.first_frame_check().checked) {
    row("frames with intersections", "not checked (--no-frame-check)");
  } else if (s.frames_with_intersections == 0) {
    row("frames with intersections", "0");
  } else {
    row("frames with intersections",
        fmt::format("{} (first: frame {}, {})", s.frames_with_intersections,
                    s.first_intersecting_frame,
                    file_name(frames.path(s.first_intersecting_frame))));
  }
  row("ms per step", fmt::format("{:.3f} (detection {:.3f}, waiting for frames {:.3f})",
                                 s.ms_per_step(), s.steps > 0 ? s.detect_ms / s.steps : 0.0,
                                 s.steps > 0 ? s.read_wait_ms / s.steps : 0.0));
  row("static check ms per frame",
      fmt::format("{:.3f}", s.frames > 0 ? s.check_ms / s.frames : 0.0));
  row("setup ms", fmt::format("{:.3f} (first frame, detector, first check)", s.setup_ms));
  for (std::size_t i = 0; i < s.intersecting_frames.size() && i < 10; ++i) {
    fmt::print("  intersecting frame {} ({})\n", s.intersecting_frames[i],
               file_name(frames.path(s.intersecting_frames[i])));
  }
  if (s.intersecting_frames.size() > 10) {
    fmt::print("  ... and {} more intersecting frames\n", s.intersecting_frames.size() - 10);
  }
}

int run_check(const CheckArgs& args) {
  const InterruptGuard interrupt;
  const FrameSources sources = resolve_frame_sources(args.frames, args.obstacle);
  SequenceCheckOptions options;
  options.detection = args.detection.config();
  std::optional<tbb::global_control> parallelism;
  if (options.detection.threads > 0) {
    parallelism.emplace(tbb::global_control::max_allowed_parallelism,
                        static_cast<std::size_t>(options.detection.threads));
  }
  std::unique_ptr<JsonLinesFile> json_lines;
  if (!args.json_lines_path.empty())
    json_lines = std::make_unique<JsonLinesFile>(args.json_lines_path);

  options.first_frame = args.from.value_or(0);
  options.last_frame = args.to.value_or(-1);
  options.check_frames = !args.no_frame_check;
  options.max_pairs = args.max_pairs;
  options.read_ahead = args.read_ahead;
  std::optional<FrameSequence> obstacle;
  if (!sources.obstacle.empty()) obstacle.emplace(sources.obstacle);
  spdlog::info("checking {} frames {}{}", sources.frames.size(), sources.frames_pattern,
               sources.obstacle.empty() ? std::string()
               : sources.obstacle_from_layout
                   ? fmt::format(" with {} beside them as the obstacle", sources.obstacle_pattern)
                   : fmt::format(" with the obstacle {}", sources.obstacle_pattern));
  FrameSequence cloth(sources.frames);
  if (!args.observers_path.empty())
    options.section_loops = read_observer_loops(args.observers_path, cloth.num_vertices());
  SequenceChecker checker(std::move(cloth), std::move(obstacle), options);

  ProgressBar progress(checker.num_steps(), "step");
  bool interrupted = false;
  std::exception_ptr error;
  while (true) {
    if (interrupt.interrupted()) {
      interrupted = checker.summary().steps < checker.num_steps();
      break;
    }
    std::optional<StepCheck> step;
    try {
      step = checker.next_step();
    } catch (const InputError&) {
      error = std::current_exception();
      break;
    }
    if (!step) break;
    if (json_lines) json_lines->write(step_json(*step));
    const SequenceSummary& s = checker.summary();
    progress.update(
        s.steps, fmt::format("{:.1f} ms/step  contacts in {} steps  intersecting "
                             "frames {}",
                             s.ms_per_step(), s.steps_with_contacts, s.frames_with_intersections));
  }
  progress.finish();
  print_summary(checker, sources, args.detection.method, interrupted, error != nullptr);
  if (error) std::rethrow_exception(error);
  if (interrupted) spdlog::warn("interrupted after step {}", checker.summary().steps);
  if (!checker.summary().intersection_free()) return kFailure;
  return interrupted ? kInterruptedExitCode : kSuccess;
}

const CommandRegistration check_registration{
    "check", [](CLI::App& app) -> std::function<int()> {
      auto args = std::make_shared<CheckArgs>();
      CLI::App* command = app.add_subcommand(
          "check", "Self-collisions of every step and intersections of every frame of a sequence");
      command
          ->add_option("FRAMES", args->frames,
                       "A folder, a glob ('out/cloth_*.obj'), a printf pattern "
                       "(out/cloth_%04d.obj) or the frame files; natural order. A folder "
                       "written by `tailor simulate` checks cloth_*.obj with arm_*.obj as "
                       "the obstacle")
          ->required()
          ->expected(-1);
      command->add_option("--obstacle", args->obstacle,
                          "Obstacle frames (folder, glob or pattern): one frame, or one per frame");
      command->add_option("--json-lines", args->json_lines_path,
                          "Write one JSON record per step to this file as each step ends");
      command
          ->add_option("--observers", args->observers_path,
                       "Radial-view section loops: JSON {\"loops\": [[vertex ids], ...]}")
          ->check(CLI::ExistingFile);
      command->add_option("--from", args->from, "First frame (0-based position in the sequence)")
          ->check(CLI::NonNegativeNumber);
      command->add_option("--to", args->to, "Last frame (inclusive; default: the last)")
          ->check(CLI::NonNegativeNumber);
      command->add_flag("--no-frame-check", args->no_frame_check,
                        "Skip the static intersection check of every frame (steps only)");
      command
          ->add_option("--read-ahead", args->read_ahead,
                       "Frames read ahead on a second thread (0: read between steps; default: "
                       "as many as fit in 64 MiB, 2 to 64)")
          ->check(CLI::Range(0, 64));
      command
          ->add_option("--max-pairs", args->max_pairs, "Intersecting face pairs listed per frame")
          ->check(CLI::Range(0, 1000000))
          ->capture_default_str();
      args->detection.add_to(*command);
      return [args] { return run_check(*args); };
    }};

}  // namespace
}  // namespace tailor::cli
