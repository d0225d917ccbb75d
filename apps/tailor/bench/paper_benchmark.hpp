#pragma once
/// @file
/// `tailor bench paper`: the paper's Fig. 1 and Table 1 on our sleeve (elbow gesture).

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bench/paper_figures.hpp"
#include "tailor/detection/detection_config.hpp"
#include "tailor/scene/scene.hpp"

namespace tailor {

/// Per-step figures of one configuration's run.
struct PaperRun {
  std::string name;
  DetectionConfig config;
  std::vector<std::int64_t> ctps, vf, ee, self_collisions;  ///< per substep (first pass)
  std::vector<double> detect_ms, step_ms;                   ///< per substep
  double wall_seconds = 0;
  int frames = 0;
  double fps() const { return wall_seconds > 0 ? frames / wall_seconds : 0; }
};

/// All runs of the experiment, and whether every run found the same self-collisions at
/// every step.
struct PaperBenchmark {
  std::vector<PaperRun> runs;  ///< basic, curtis, tang, paper, normal_cones, radial_view
  bool same_collisions = true;
  std::string mismatch;  ///< first difference, when not the same

  /// Fig. 1 as pictures (peak flexion), written by write().
  std::shared_ptr<PaperFigures> figures;

  /// The run named `name` (one of the above).
  const PaperRun& run(const std::string& name) const;
  /// Fig. 1 as CSV: step,basic,normal_cones,radial_view,isolated_set.
  std::string fig1_csv() const;
  /// Fig. 1 means as a Markdown table.
  std::string fig1_markdown() const;
  /// Table 1 as CSV: method,vf,ee,detect_ms,step_ms,fps.
  std::string table1_csv() const;
  /// Table 1 as Markdown, beside the paper's published rows.
  std::string table1_markdown() const;
  /// Writes the CSV, Markdown and SVG files into `dir` (created if needed).
  void write(const std::filesystem::path& dir) const;
};

/// Runs the scene once per configuration; `progress(run, frame, frames)` after each frame.
PaperBenchmark run_paper_benchmark(
    const SceneConfig& scene,
    const std::function<void(const std::string&, int, int)>& progress = {});

}  // namespace tailor
