#pragma once
/// @file
/// `tailor bench paper`: the paper's Fig. 1 and Table 1 on our sleeve (elbow gesture by
/// default; raise and twist too).

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
  /// Radial-view classification per substep (first pass): real and ghost triangles
  /// positive, negative and undetermined against their observers, summed over clusters.
  std::vector<std::int64_t> radial_positive, radial_negative, radial_undetermined;
  std::vector<double> detect_ms, step_ms;  ///< per substep
  double wall_seconds = 0;
  int frames = 0;
  double fps() const { return wall_seconds > 0 ? frames / wall_seconds : 0; }
};

/// All runs of the experiment, and whether every run found the same self-collisions at
/// every step.
struct PaperBenchmark {
  std::string gesture;         ///< the scene's gesture
  std::vector<PaperRun> runs;  ///< basic, curtis, tang, paper, normal_cones, radial_view
  bool same_collisions = true;
  std::string mismatch;  ///< first difference, when not the same

  /// Fig. 1 as pictures (peak flexion), written by write().
  std::shared_ptr<PaperFigures> figures;

  /// The run named `name` (one of the above).
  const PaperRun& run(const std::string& name) const;
  /// Fig. 1 as CSV: step,basic,normal_cones,radial_view,isolated_set,tang, then the
  /// paper run's classification shares positive,negative,undetermined (0 to 1).
  std::string fig1_csv() const;
  /// Fig. 1 means as a Markdown table, with Tang's configuration (normal cones + isolated
  /// set, no radial view), the ratios the paper claims and the classification shares.
  std::string fig1_markdown() const;
  /// Whether every stage of Fig. 1 lowers the mean CTPs (basic > + normal cones >
  /// + radial view > + isolated set), or had nothing left to lower (a mean of 0).
  bool fig1_stages_decrease() const;
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
