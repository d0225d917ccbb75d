/// @file
/// `tailor simulate`: runs the arm-sleeve scene and writes OBJ frames, steps.jsonl and
/// summary.json (the simulation itself is tailor::Simulation).

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <tbb/global_control.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <limits>
#include <optional>
#include <utility>
#include <string>

#include "command.hpp"
#include "interrupt.hpp"
#include "progress.hpp"
#include "thread_limit.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/render/animation.hpp"
#include "tailor/render/run_renderer.hpp"
#include "tailor/scene/scene.hpp"
#include "tailor/sim/frame_writer.hpp"
#include "tailor/sim/simulation.hpp"

namespace tailor::cli {
namespace {

struct SimulateOptions {
  std::string scene;
  std::string gesture;
  int frames = -1;
  std::string method = "paper";
  std::string out = "out/sleeve";
  int rings = 0, segments = 0;
  bool check_every_step = false;
  bool check_frames = false;
  bool contacts = true;
  bool render = false;
  int threads = 0;
};

/// A box around every position the arm takes during the run (from the gesture, so the
/// camera is fixed before the first frame) and the sleeve's rest shape.
std::pair<Vec3, Vec3> run_bounds(const Simulation& sim) {
  const Scene& scene = sim.scene();
  const SceneConfig& c = scene.config();
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  const auto extend = [&](const Positions& x) {
    for (Eigen::Index i = 0; i < x.rows(); ++i) {
      lo = lo.cwiseMin(x.row(i).transpose());
      hi = hi.cwiseMax(x.row(i).transpose());
    }
  };
  extend(sim.cloth_positions());
  // The pose holds after the gesture's last key: frames past it add nothing (a run of
  // 100,000 frames used to skin the arm 100,000 times before its first frame).
  const double duration = scene.gesture().duration();
  for (int f = 0; f <= c.frames; ++f) {
    extend(scene.arm().skin(scene.gesture().pose_at(f * c.time_step)));
    if (f * c.time_step > duration) break;
  }
  return {lo, hi};
}

void print_table(const nlohmann::json& s) {
  const auto& row = print_summary_row;
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
      s["checked_steps"].get<std::int64_t>() == 0
          ? std::string("not run (--check-frames, --check-intersections)")
          : fmt::format("{} in {} checked steps", s["intersections"].get<std::int64_t>(),
                        s["checked_steps"].get<std::int64_t>()));
  row("reverted vertices / unresolved",
      fmt::format("{} / {}", s["reverted_vertices"].get<std::int64_t>(),
                  s["unresolved"].get<std::int64_t>()));
  row("edge strain max / p99",
      fmt::format("{:.2f} % / {:.2f} %", 100 * s["strain"]["max"].get<double>(),
                  100 * s["strain"]["p99_max"].get<double>()));
  row("forces+solve ms/step", fmt::format("{:.3f}", ms["forces_solve"].get<double>()));
  row("  assembly / factor+solve",
      fmt::format("{:.3f} / {:.3f}", ms["assemble"].get<double>(), ms["solve"].get<double>()));
  row("  strain limit + arm", fmt::format("{:.3f}", ms["strain_limit"].get<double>()));
  row("detection ms/step", fmt::format("{:.3f}", ms["detection"].get<double>()));
  row("response ms/step", fmt::format("{:.3f}", ms["response"].get<double>()));
  row("static check ms/step", fmt::format("{:.3f}", ms["check"].get<double>()));
  row("whole step ms/step", fmt::format("{:.3f}", ms["total"].get<double>()));
  row("frames per second", fmt::format("{:.2f}", s["frames_per_second"].get<double>()));
}

int run_simulate(const SimulateOptions& o) {
  // Installed first, so a Ctrl-C during setup also ends after the first frame.
  const InterruptGuard interrupt;
  SceneConfig config = o.scene.empty() ? SceneConfig{} : load_scene_config(o.scene);
  if (!o.gesture.empty()) config.gesture.name = o.gesture;
  if (o.frames >= 0) config.frames = o.frames;
  if (o.rings > 0) config.sleeve.rings = o.rings;
  if (o.segments > 0) config.sleeve.segments = o.segments;
  SimulationOptions options;
  options.detection = DetectionConfig::preset(o.method);
  options.detection.threads = o.threads;
  options.check_intersections = o.check_every_step;
  // The independent static check only on request (it was 7 % of a default substep): the
  // contact solver certifies every substep itself and reports what it could not resolve.
  options.check_frames = o.check_frames;
  options.record_contacts = o.contacts;

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
  if (o.contacts) {
    const std::vector<Index> clusters = sim.cluster_of_face();
    if (!clusters.empty()) writer.write_clusters(clusters);
  }
  // Pictures on the fly: the contact sheet always (cheap), every frame with --render.
  const auto [lo, hi] = run_bounds(sim);
  RunRenderer pictures(o.out, lo, hi, config.frames);
  pictures.set_write_frames(o.render);
  const auto draw = [&](int frame, const std::vector<StepRecord>* records) {
    FrameView view;
    view.arm = &sim.arm_positions();
    view.arm_faces = &arm_faces;
    view.cloth = &sim.cloth_positions();
    view.cloth_faces = &cloth_faces;
    if (records != nullptr) {
      for (const StepRecord& r : *records)
        view.highlighted_faces.insert(view.highlighted_faces.end(),
                                      r.contact.candidate_faces.begin(),
                                      r.contact.candidate_faces.end());
    }
    pictures.add_frame(frame, view);
  };
  draw(0, nullptr);
  spdlog::info(
      "simulating '{}' ({} frames, {} substeps, sleeve {}×{} = {} vertices, method {}) into {}",
      config.gesture.name, config.frames, config.substeps, config.sleeve.rings,
      config.sleeve.segments, sim.cloth_mesh().num_vertices(), o.method, o.out);

  ProgressBar progress(config.frames, "frame");
  bool interrupted = false;
  for (int f = 0; f < config.frames; ++f) {
    const auto& records = sim.step_frame();
    writer.write_frame(sim.frame(), sim.cloth_positions(), cloth_faces, sim.arm_positions(),
                       arm_faces);
    writer.append_steps(records);
    if (o.contacts) writer.write_contacts(sim.frame(), records, sim.observer_positions());
    draw(sim.frame(), &records);
    if (progress.enabled()) {
      const auto& t = sim.totals();
      progress.update(sim.frame(), fmt::format("{:.1f} fps  self-collisions {}",
                                               t.wall_seconds > 0 ? t.frames / t.wall_seconds : 0.0,
                                               t.self_collisions));
    }
    if (interrupt.interrupted() && f + 1 < config.frames) {
      interrupted = true;
      break;
    }
  }
  progress.finish();
  const std::filesystem::path sheet = pictures.finish();
  nlohmann::json summary = simulation_summary(sim, interrupted);
  summary["method"] = o.method;
  writer.write_summary(summary);
  print_table(summary);
  fmt::print("  {:<30} {}{}\n", "pictures", sheet.string(),
             o.render ? fmt::format(" and render_NNNN.png ({} frames)", sim.frame() + 1) : "");
  if (o.render) {
    // Played at the simulation's own frame rate.
    const AnimationResult animation = write_animation(o.out, 1.0 / config.time_step);
    fmt::print("  {:<30} {}\n", "animation",
               animation.written ? animation.path.string() : "not written: " + animation.reason);
  }
  if (interrupted) spdlog::warn("interrupted after frame {}", sim.frame());
  const std::int64_t intersections = summary["intersections"].get<std::int64_t>();
  if (intersections > 0) {
    spdlog::error("the static check found {} intersections", intersections);
    return kFailure;
  }
  const std::int64_t unresolved = summary["unresolved"].get<std::int64_t>();
  if (unresolved > 0) {
    spdlog::error("the contact solver left {} collisions unresolved", unresolved);
    return kFailure;
  }
  return interrupted ? kInterruptedExitCode : kSuccess;
}

const CommandRegistration simulate_registration{
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
      cmd->add_flag("--check-intersections", o->check_every_step,
                    "Run the static intersection check after every substep");
      cmd->add_flag("--check-frames", o->check_frames,
                    "Run the static intersection check after every frame (the contact solver "
                    "certifies every substep either way; exit 1 if anything is found)");
      cmd->add_flag("--render", o->render,
                    "Also write a PNG of every frame (render_NNNN.png) and animation.mp4 (ffmpeg; "
                    "contact_sheet.png is "
                    "always written)");
      cmd->add_flag("!--no-contacts", o->contacts,
                    "Do not write the per-frame contact files (contacts_NNNN.json, clusters.json)");
      cmd->add_option("--threads", o->threads, "Worker threads (0: all)")
          ->check(thread_count_validator());
      return [o] { return run_simulate(*o); };
    }};

}  // namespace
}  // namespace tailor::cli
