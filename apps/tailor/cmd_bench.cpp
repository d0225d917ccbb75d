/// @file
/// `tailor bench paper` and `tailor bench scale`: regenerate every figure we claim.

#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "command.hpp"
#include "bench/paper_benchmark.hpp"
#include "bench/scale_benchmark.hpp"
#include "bench/svg_plot.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/io/file_bytes.hpp"
#include "tailor/io/memory_budget.hpp"
#include "tailor/scene/gesture.hpp"
#include "tailor/scene/scene.hpp"

namespace tailor::cli {
namespace {

struct BenchArgs {
  std::string out = "out/bench";
  std::string scene_path;
  std::string gesture = "elbow";
  int frames = 0;
  Index min_triangles = 10'000;
  Index max_triangles = 1'000'000;
  int repetitions = 3;
  double min_seconds = 0.5;
  std::vector<std::string> scenes = scale_scene_names();
  std::vector<int> threads = {1, 2};
  // `bench memory` (run by `bench scale` in a child process).
  std::string memory_scene = "cloth";
  Index memory_triangles = 10'000;
  int memory_threads = 1;
};

bool on_terminal() {
  return isatty(fileno(stderr)) != 0;
}

int run_paper(const BenchArgs& args) {
  prepare_output_folder(args.out);  // before the runs, not after them
  SceneConfig scene = args.scene_path.empty() ? SceneConfig{} : load_scene_config(args.scene_path);
  scene.gesture.name = args.gesture;
  if (args.frames > 0) scene.frames = args.frames;
  const bool terminal = on_terminal();
  const PaperBenchmark bench =
      run_paper_benchmark(scene, [&](const std::string& run, int frame, int frames) {
        if (terminal) fmt::print(stderr, "\r{:<14} frame {:>4}/{}", run, frame, frames);
        if (terminal && frame == frames) fmt::print(stderr, "\n");
      });
  bench.write(args.out);
  fmt::print("## Fig. 1: candidate triangle pairs ({} gesture, {} frames)\n\n{}\n",
             scene.gesture.name, scene.frames, bench.fig1_markdown());
  fmt::print("## Table 1: pairs reaching the exact CCD per step, and frame rate\n\n{}\n",
             bench.table1_markdown());
  if (!bench.same_collisions) {
    fmt::print("self-collisions DIFFER between configurations: {}\n", bench.mismatch);
    return kFailure;
  }
  fmt::print("every configuration found the same self-collisions at every step ({} steps)\n",
             bench.runs.front().self_collisions.size());
  fmt::print("written to {}/\n", args.out);
  return kSuccess;
}

// Runs this executable with `arguments` and returns what it printed; throws when it fails.
std::string run_self(const std::vector<std::string>& arguments) {
  std::error_code error;
  const std::string exe = std::filesystem::read_symlink("/proc/self/exe", error).string();
  if (error) throw std::runtime_error("cannot find this executable: " + error.message());
  std::vector<char*> argv{const_cast<char*>(exe.c_str())};
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  int pipe_ends[2];
  if (pipe(pipe_ends) != 0) throw std::runtime_error("cannot open a pipe to a child process");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_ends[0]);
  pid_t child = 0;
  const int spawned = posix_spawn(&child, exe.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_ends[1]);
  std::string output;
  char buffer[256];
  for (ssize_t n; spawned == 0 && (n = read(pipe_ends[0], buffer, sizeof buffer)) > 0;) {
    output.append(buffer, static_cast<std::size_t>(n));
  }
  close(pipe_ends[0]);
  int status = 0;
  if (spawned != 0 || waitpid(child, &status, 0) != child || !WIFEXITED(status) ||
      WEXITSTATUS(status) != 0) {
    std::string command = exe;
    for (const std::string& argument : arguments) command += " " + argument;
    throw std::runtime_error(fmt::format("`{}` failed: {}", command, output));
  }
  return output;
}

// `bench memory`: one scene's bytes per triangle, alone in this process.
int run_memory(const BenchArgs& args) {
  fmt::print("{:.3f}\n", scale_bytes_per_triangle(args.memory_scene, args.memory_triangles,
                                                  args.memory_threads));
  return kSuccess;
}

int run_scale(const BenchArgs& args) {
  if (args.min_triangles > args.max_triangles) {
    throw InputError(fmt::format("--min-triangles {} is above --max-triangles {}",
                                 args.min_triangles, args.max_triangles));
  }
  prepare_output_folder(args.out);  // before the runs, not after them
  ScaleOptions options;
  options.scenes = args.scenes;
  options.min_triangles = args.min_triangles;
  options.max_triangles = args.max_triangles;
  options.threads = args.threads;
  options.repetitions = args.repetitions;
  options.min_seconds = args.min_seconds;
  // Memory in a fresh process per row: in this one, each scene's figure would carry the
  // allocator's state from the scenes before it.
  options.memory_probe = [](const std::string& scene, Index triangles, int threads) {
    return std::stod(run_self({"--max-memory",
                               fmt::format("{}", static_cast<double>(memory_budget()) / (1 << 30)),
                               "bench", "memory", "--scene", scene, "--triangles",
                               std::to_string(triangles), "--threads", std::to_string(threads)}));
  };
  const bool terminal = on_terminal();
  options.progress = [&](const std::string& what) {
    if (terminal) fmt::print(stderr, "\r{:<60}", what);
  };
  const std::vector<ScaleRow> rows = run_scale_benchmark(options);
  if (terminal) fmt::print(stderr, "\r{:<60}\r", "");
  std::filesystem::create_directories(args.out);
  write_file_atomically(std::filesystem::path(args.out) / "scale.csv", scale_csv(rows));
  write_file_atomically(std::filesystem::path(args.out) / "scale.md", scale_markdown(rows));
  scale_plot(rows).write(std::filesystem::path(args.out) / "scale.svg");
  fmt::print("{}", scale_markdown(rows));
  fmt::print(
      "Milliseconds per step (median of at least {} steps and {} s per row), preset paper; floor "
      "= every face's swept box from x0 and x1; refit* = the direction masks alone (the root "
      "stayed certified: no box was needed); B/triangle = peak memory of topology + detector + "
      "step buffers, each row in a fresh process; speed-up = the first thread count's step over "
      "this one's, median of paired rounds (one step of each thread count in turn).\n",
      args.repetitions, args.min_seconds);
  fmt::print("written to {}/\n", args.out);
  return kSuccess;
}

const CommandRegistration bench_registration{
    "bench", [](CLI::App& app) {
      auto args = std::make_shared<BenchArgs>();
      CLI::App* bench = app.add_subcommand("bench", "Reproduce the paper's experiment and scaling");
      bench->require_subcommand(1);
      CLI::App* paper = bench->add_subcommand(
          "paper", "Fig. 1 and Table 1 on the sleeve with a gesture (one run per method)");
      paper->add_option("--gesture", args->gesture, "Gesture the arm plays")
          ->check(CLI::IsMember(gesture_names()))
          ->capture_default_str();
      paper->add_option("--out", args->out, "Output folder")->capture_default_str();
      paper->add_option("--scene", args->scene_path, "Scene file (default: built-in sleeve)")
          ->check(CLI::ExistingFile);
      paper->add_option("--frames", args->frames, "Frames per run (default: the scene's)")
          ->check(CLI::PositiveNumber);
      CLI::App* scale = bench->add_subcommand(
          "scale",
          "Per-stage cost from 10K to 1M triangles (cloth, folded cloth, bending sleeve), "
          "1 and 2 threads, with the floor, pairs per collision and memory");
      scale->add_option("--out", args->out, "Output folder")->capture_default_str();
      scale->add_option("--min-triangles", args->min_triangles, "Smallest mesh")
          ->check(CLI::Range(200, 50'000'000))
          ->capture_default_str();
      scale->add_option("--max-triangles", args->max_triangles, "Largest mesh")
          ->check(CLI::Range(200, 50'000'000))
          ->capture_default_str();
      scale->add_option("--scenes", args->scenes, "Scenes to run")
          ->check(CLI::IsMember(scale_scene_names()))
          ->capture_default_str();
      scale->add_option("--threads", args->threads, "Thread counts to run")
          ->check(CLI::Range(1, 256))
          ->capture_default_str();
      scale
          ->add_option("--repetitions", args->repetitions,
                       "Timed steps per configuration, at least")
          ->check(CLI::Range(1, 100))
          ->capture_default_str();
      scale
          ->add_option("--min-seconds", args->min_seconds,
                       "More timed steps while a configuration's took less than this")
          ->check(CLI::Range(0.0, 600.0))
          ->capture_default_str();
      // Hidden (no group): the memory of one row, which `bench scale` runs in a child.
      CLI::App* memory = bench->add_subcommand("memory", "One row's memory (bench scale)");
      memory->group("");
      memory->add_option("--scene", args->memory_scene)->check(CLI::IsMember(scale_scene_names()));
      memory->add_option("--triangles", args->memory_triangles)->check(CLI::Range(200, 50'000'000));
      memory->add_option("--threads", args->memory_threads)->check(CLI::Range(1, 256));
      return [args, paper, memory] {
        if (paper->parsed()) return run_paper(*args);
        return memory->parsed() ? run_memory(*args) : run_scale(*args);
      };
    }};

}  // namespace
}  // namespace tailor::cli
