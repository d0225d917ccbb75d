#pragma once
/// @file
/// `tailor bench scale`: per-stage cost of detection from 10K to 1M+ triangles on three
/// scenes, with the floor, pairs per real collision, thread scaling and memory.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "bench/svg_plot.hpp"
#include "tailor/geometry/types.hpp"

namespace tailor {

/// One measured configuration: a scene at one size and thread count.
struct ScaleRow {
  std::string scene;  ///< "cloth", "folded", "pleated" or "sleeve" (see ScaleOptions::scenes)
  int threads = 1;
  Index triangles = 0;
  double floor_ms = 0;  ///< read x0 and x1 and compute every face's swept box (same threads)
  /// The first thread count's whole step over this one's, median over rounds that time one
  /// step of each thread count in turn (paired, so the machine's drifts cancel); 1 for the
  /// first thread count.
  double speedup = 1;
  double refit_ms = 0, traversal_ms = 0, radial_view_ms = 0, low_level_ms = 0, ccd_ms = 0,
         total_ms = 0;
  /// Whether the timed steps refitted the BVH's boxes: false when the root stayed certified
  /// from step to step, and the refit was the direction masks alone.
  bool boxes_refitted = true;
  std::int64_t ctps = 0, vf = 0, ee = 0, collisions = 0;
  /// Peak memory of the detector (topology, BVH, culling data, buffers of two steps) per
  /// triangle: the rise of the peak resident set size over its value before the mesh
  /// topology was built; the positions of the scene are not counted. Measured in a fresh
  /// process when ScaleOptions::memory_probe is set.
  double bytes_per_triangle = 0;
  double peak_mib = 0;  ///< peak resident memory of the whole process so far

  /// Pairs that reached the exact CCD per collision found (0 without collisions).
  double pairs_per_collision() const {
    return collisions > 0 ? static_cast<double>(vf + ee) / static_cast<double>(collisions) : 0;
  }
};

/// What to run.
struct ScaleOptions {
  /// Scenes: "cloth" (a square cloth crumpling between t=0.5 and 0.51: no contact),
  /// "folded" (make_folded_cloth_on_sphere: ~1 colliding pair per triangle), "pleated"
  /// (make_pleated_cloth: ~35 candidate triangle pairs and ~2 collisions per triangle, the
  /// density of real contact) and "sleeve"
  /// (a sleeve-proportioned tube bending 1° at its middle, radial-view observers).
  std::vector<std::string> scenes = {"cloth", "folded", "pleated", "sleeve"};
  Index min_triangles = 10'000;
  Index max_triangles = 1'000'000;
  std::vector<int> threads = {1, 2};
  int repetitions = 3;  ///< timed steps per configuration, at least (the median is kept)
  /// More steps while a configuration's timed steps took less than this (s): a step of a
  /// few milliseconds varies by more than the thread scaling it should show when it is
  /// timed only three times.
  double min_seconds = 0.5;
  std::function<void(const std::string&)> progress;  ///< called before each configuration
  /// When set, gives ScaleRow::bytes_per_triangle for (scene, target triangles, threads),
  /// e.g. from scale_bytes_per_triangle() in a fresh process. Otherwise it is measured in
  /// this process, where it moves by tens of bytes with what the process did before (the
  /// allocator's free lists and its mmap threshold keep the history of earlier scenes).
  std::function<double(const std::string&, Index, int)> memory_probe;
};

/// ScaleRow::bytes_per_triangle of a scene of about `target_triangles` on `threads`
/// threads, measured in this process (the CLI runs it alone in a child process) after a
/// run on a small mesh of the same scene, which pays what a process pays once.
double scale_bytes_per_triangle(const std::string& scene, Index target_triangles, int threads);

/// The scene names run_scale_benchmark accepts.
std::vector<std::string> scale_scene_names();

/// Runs every scene at sizes min_triangles·√10^k up to max_triangles, for each thread
/// count, preset `paper`; the thread counts of a size are timed in alternation (one step
/// each per round). Throws InputError for an unknown scene.
std::vector<ScaleRow> run_scale_benchmark(const ScaleOptions& options);

/// CSV with one row per ScaleRow (header included).
std::string scale_csv(const std::vector<ScaleRow>& rows);
/// Markdown table of the rows.
std::string scale_markdown(const std::vector<ScaleRow>& rows);
/// Log-log plot of total and floor milliseconds against triangles.
LinePlot scale_plot(const std::vector<ScaleRow>& rows);

}  // namespace tailor
