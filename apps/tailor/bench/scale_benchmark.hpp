#pragma once
/// @file
/// `tailor bench scale`: per-stage cost of detection from 1K to 1M+ triangles.

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
  std::string scene;  ///< "cloth" (crumpling grid) or "sleeve" (bending tube)
  int threads = 1;
  Index triangles = 0;
  double floor_ms = 0;  ///< refit of boxes and cones alone
  double refit_ms = 0, traversal_ms = 0, low_level_ms = 0, ccd_ms = 0, total_ms = 0;
  std::int64_t ctps = 0, vf = 0, ee = 0, collisions = 0;
  double peak_mib = 0;  ///< peak resident memory of the process so far
};

/// What to run.
struct ScaleOptions {
  Index max_triangles = 1'000'000;
  int repetitions = 3;  ///< timed steps per configuration (the median is kept)
  std::function<void(const std::string&)> progress;  ///< called before each configuration
};

/// Runs the crumpling cloth and the bending sleeve tube at sizes 1K, 3K, 10K, ... up to
/// `max_triangles`, with 1 and 2 threads, preset `paper`.
std::vector<ScaleRow> run_scale_benchmark(const ScaleOptions& options);

/// CSV with one row per ScaleRow (header included).
std::string scale_csv(const std::vector<ScaleRow>& rows);
/// Log-log plot of total and floor milliseconds against triangles.
LinePlot scale_plot(const std::vector<ScaleRow>& rows);

}  // namespace tailor
