/// @file
/// `tailor simulate`: runs the arm-sleeve scene and writes OBJ frames, steps.jsonl and
/// summary.json (the simulation itself is tailor::Simulation).

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "command.hpp"
#include "thread_limit.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/scene/scene.hpp"
#include "tailor/sim/frame_writer.hpp"
#include "tailor/sim/simulation.hpp"

namespace tailor::cli {
namespace {

volatile std::sig_atomic_t g_interrupted = 0;

extern "C" void on_sigint(int) {
  if (g_interrupted != 0) {
    // Second Ctrl-C: stop now.
    std::signal(SIGINT, SIG_DFL);
    std::raise(SIGINT);
  }
  g_interrupted = 1;
}

struct SimulateOptions {
  std::string scene;
  std::string gesture;
  int frames = -1;
  std::string method = "paper";
  std::string out = "out/sleeve";
  int rings = 0, segments = 0;
  bool check_every_step = false;
  int threads = 0;
};

void print_progress(int frame, int frames, double fps, std::int64_t collisions) {
  const int width = 30;
  const int filled = frames > 0 ? width * frame / frames : width;
  fmt::print(stderr, "\r[{}{}] frame {}/{}  {:.1f} fps  self-collisions {}   ",
             std::string(static_cast<std::size_t>(filled), '#'),
             std::string(static_cast<std::size_t>(width - filled), '.'), frame, frames, fps,
             collisions);
  std::fflush(stderr);
}

void print_table(const nlohmann::json& s) {
  const auto row = [](const char* name, const std::string& value) {
    fmt::print("  {:<30} {}\n", name, value);
  };
  const auto mean_max = [&](const nlohmann::json& j) {
    return fmt::format("{:.1f} mean, {} max", j["mean"].get<double>(),
                       j["max"].get<std::int64_t>());
  };
  const auto& ms = s["ms_per_step"];
  fmt::print("\nsimulation summary\n");
  row("frames", fmt::format("{}{}", s["frames"].get<int>(),
                            s["interrupted"].get<bool>() ? " (interrupted)" : ""));
  row("steps", std::to_string(s["steps"].get<std::int64_t>()));
  row("cloth vertices / faces",
      fmt::format("{} / {}", s["cloth"]["vertices"].get<int>(), s["cloth"]["faces"].get<int>()));
  row("candidate triangle pairs", mean_max(s["candidate_triangle_pairs"]));
  row("VF pairs tested", mean_max(s["vf_tested"]));
  row("EE pairs tested", mean_max(s["ee_tested"]));
  row("self-collisions (total)", std::to_string(s["self_collisions"].get<std::int64_t>()));
  row("arm collisions (total)", std::to_string(s["obstacle_collisions"].get<std::int64_t>()));
  row("impulses / impact zones", fmt::format("{} / {}", s["impulses"].get<std::int64_t>(),
                                             s["impact_zones"].get<std::int64_t>()));
  row("intersections (static check)",
      fmt::format("{} in {} checked steps", s["intersections"].get<std::int64_t>(),
                  s["checked_steps"].get<std::int64_t>()));
  row("forces+solve ms/step", fmt::format("{:.3f}", ms["forces_solve"].get<double>()));
  row("detection ms/step", fmt::format("{:.3f}", ms["detection"].get<double>()));
  row("response ms/step", fmt::format("{:.3f}", ms["response"].get<double>()));
  row("whole step ms/step", fmt::format("{:.3f}", ms["total"].get<double>()));
  row("frames per second", fmt::format("{:.2f}", s["frames_per_second"].get<double>()));
}

int run_simulate(const SimulateOptions& o) {
  // Installed first, so a Ctrl-C during setup also ends after the first frame.
  g_interrupted = 0;
  const auto previous = std::signal(SIGINT, on_sigint);
  struct RestoreSignal {
    decltype(previous) handler;
    ~RestoreSignal() { std::signal(SIGINT, handler); }
  } restore{previous};
  SceneConfig config = o.scene.empty() ? SceneConfig{} : load_scene_config(o.scene);
  if (!o.gesture.empty()) config.gesture.name = o.gesture;
  if (o.frames >= 0) config.frames = o.frames;
  if (o.rings > 0) config.sleeve.rings = o.rings;
  if (o.segments > 0) config.sleeve.segments = o.segments;
  SimulationOptions options;
  options.detection = DetectionConfig::preset(o.method);
  options.detection.threads = o.threads;
  options.check_intersections = o.check_every_step;
  options.check_frames = true;  // cheap at the default size; every substep on request

  std::optional<tbb::global_control> parallelism;
  if (o.threads > 0) {
    parallelism.emplace(tbb::global_control::max_allowed_parallelism,
                        static_cast<std::size_t>(o.threads));
  }

  Simulation sim(config, options);
  FrameWriter writer(o.out);
  const auto& cloth_faces = sim.cloth_mesh().faces();
  const auto& arm_faces = sim.arm_mesh().faces();
  writer.write_frame(0, sim.cloth_positions(), cloth_faces, sim.arm_positions(), arm_faces);
  spdlog::info(
      "simulating '{}' ({} frames, {} substeps, sleeve {}×{} = {} vertices, method {}) into {}",
      config.gesture.name, config.frames, config.substeps, config.sleeve.rings,
      config.sleeve.segments, sim.cloth_mesh().num_vertices(), o.method, o.out);

  const bool tty = isatty(fileno(stderr)) != 0;
  bool interrupted = false;
  for (int f = 0; f < config.frames; ++f) {
    const auto& records = sim.step_frame();
    writer.write_frame(sim.frame(), sim.cloth_positions(), cloth_faces, sim.arm_positions(),
                       arm_faces);
    writer.append_steps(records);
    if (tty) {
      const auto& t = sim.totals();
      print_progress(sim.frame(), config.frames,
                     t.wall_seconds > 0 ? t.frames / t.wall_seconds : 0.0, t.self_collisions);
    }
    if (g_interrupted != 0 && f + 1 < config.frames) {
      interrupted = true;
      break;
    }
  }
  if (tty) fmt::print(stderr, "\n");
  nlohmann::json summary = simulation_summary(sim, interrupted);
  summary["method"] = o.method;
  writer.write_summary(summary);
  print_table(summary);
  if (interrupted) spdlog::warn("interrupted after frame {}", sim.frame());
  const std::int64_t intersections = summary["intersections"].get<std::int64_t>();
  if (intersections > 0) {
    spdlog::error("the static check found {} intersections", intersections);
    return kFailure;
  }
  return interrupted ? 130 : kSuccess;
}

const CommandRegistration registration{
    "simulate", [](CLI::App& app) -> std::function<int()> {
      CLI::App* cmd = app.add_subcommand("simulate", "Run the arm-sleeve cloth simulation");
      auto o = std::make_shared<SimulateOptions>();
      cmd->add_option("--scene", o->scene,
                      "Scene file (JSON); default: built-in scene (scenes/sleeve.json)");
      cmd->add_option("--gesture", o->gesture, "Gesture: elbow, raise or twist");
      cmd->add_option("--frames", o->frames, "Frames to simulate (at 30 fps by default)")
          ->check(CLI::NonNegativeNumber);
      cmd->add_option("--method", o->method, "Detection preset: basic, curtis, tang or paper")
          ->capture_default_str();
      cmd->add_option("--out", o->out, "Output folder")->capture_default_str();
      cmd->add_option("--rings", o->rings, "Sleeve rings along the arm (scales the mesh)")
          ->check(CLI::Range(2, 1 << 20));
      cmd->add_option("--segments", o->segments, "Sleeve vertices around the arm")
          ->check(CLI::Range(3, 1 << 20));
      cmd->add_flag(
          "--check-intersections", o->check_every_step,
          "Run the static intersection check after every substep (default: after every frame)");
      cmd->add_option("--threads", o->threads, "Worker threads (0: all)")
          ->check(thread_count_validator());
      return [o] { return run_simulate(*o); };
    }};

}  // namespace
}  // namespace tailor::cli
