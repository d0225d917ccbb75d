#include "bench/scale_benchmark.hpp"

#include <fmt/format.h>
#include <malloc.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <numeric>
#include <numbers>

#include "tailor/bvh/aabb.hpp"
#include "tailor/detection/self_collision_detector.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/geometry/stopwatch.hpp"
#include "tailor/mesh/procedural_meshes.hpp"
#include "tailor/mesh/procedural_steps.hpp"

namespace tailor {
namespace {

// A field of /proc/self/status in kB ("VmHWM:", "VmRSS:"), in bytes.
double status_bytes(const std::string& field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind(field, 0) == 0) return std::stod(line.substr(field.size())) * 1024.0;
  }
  return 0;
}

// Returns freed memory to the system and restarts the peak at the current resident size
// (Linux: writing 5 to clear_refs); returns that size.
double reset_peak() {
  malloc_trim(0);
  std::ofstream("/proc/self/clear_refs") << "5";
  return status_bytes("VmRSS:");
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

struct ScaleScene {
  MeshData mesh;  // vertices = x0
  Positions x1;
  std::vector<std::vector<Index>> section_loops;
};

ScaleScene from_step(ProceduralStep step) {
  ScaleScene scene;
  scene.mesh.vertices = std::move(step.x0);
  scene.mesh.faces = std::move(step.faces);
  scene.x1 = std::move(step.x1);
  return scene;
}

// A sleeve-proportioned tube (rings ≈ 0.64 × segments, as 21 × 33) bending at its middle
// like an elbow, one degree per step; observers on the rings at 1/4 and 3/4.
ScaleScene sleeve_scene(Index triangles) {
  const int segments = std::max(3, static_cast<int>(std::lround(std::sqrt(triangles / 1.28))));
  const int rings = std::max(4, static_cast<int>(std::lround(0.64 * segments)));
  const double length = 0.5, radius = 0.06;
  ScaleScene scene;
  scene.mesh = make_tube(rings, segments, radius, length);
  const Positions straight = scene.mesh.vertices;
  auto bend = [&](double angle) {
    Positions x = straight;
    for (Eigen::Index i = 0; i < x.rows(); ++i) {
      const double z = straight(i, 2);
      if (z <= 0.5 * length) continue;
      const double d = z - 0.5 * length;
      x(i, 1) = straight(i, 1) * std::cos(angle) - d * std::sin(angle);
      x(i, 2) = 0.5 * length + straight(i, 1) * std::sin(angle) + d * std::cos(angle);
    }
    return x;
  };
  scene.mesh.vertices = bend(0.9);
  scene.x1 = bend(0.9 + std::numbers::pi / 180);
  for (int r : {rings / 4, 3 * rings / 4}) {
    std::vector<Index> loop;
    for (int s = 0; s < segments; ++s) loop.push_back(r * segments + s);
    scene.section_loops.push_back(std::move(loop));
  }
  return scene;
}

ScaleScene make_scene(const std::string& name, Index triangles) {
  if (name == "cloth") return from_step(make_crumpling_cloth_step(triangles));
  if (name == "folded") return from_step(make_folded_cloth_on_sphere(triangles));
  if (name == "pleated") return from_step(make_pleated_cloth(triangles));
  return sleeve_scene(triangles);
}

// The floor: every face's swept box from x0 and x1, in parallel on the arena's threads.
double floor_ms(const FaceArray& faces, const Positions& x0, const Positions& x1,
                std::vector<Aabb>& boxes, tbb::task_arena& arena) {
  const auto start = SteadyClock::now();
  arena.execute([&] { swept_face_boxes(faces, x0, x1, boxes); });
  return milliseconds_since(start);
}

// Whether a configuration needs another timed run after `runs` runs taking `ms` in all.
bool more_runs(const ScaleOptions& options, std::size_t runs, double ms) {
  return static_cast<int>(runs) < options.repetitions || ms < 1e3 * options.min_seconds;
}

double sum(const std::vector<double>& values) {
  return std::accumulate(values.begin(), values.end(), 0.0);
}

// The detector `bench scale` measures: preset paper on `threads` threads.
std::unique_ptr<SelfCollisionDetector> paper_detector(const TriangleMesh& mesh,
                                                      const ScaleScene& scene, int threads) {
  DetectionConfig config = DetectionConfig::preset("paper");
  config.threads = threads;
  return std::make_unique<SelfCollisionDetector>(mesh, scene.mesh.vertices, config,
                                                 scene.section_loops);
}

// Peak memory per triangle of a detector on `threads` threads: the rise of the peak resident
// set size while the mesh topology and the detector are built and run two steps (the
// buffers reach their size in the first).
double bytes_per_triangle(const ScaleScene& scene, int threads) {
  const double resident_before = reset_peak();
  const TriangleMesh mesh(static_cast<Index>(scene.mesh.vertices.rows()), scene.mesh.faces);
  const auto detector = paper_detector(mesh, scene, threads);
  for (int step = 0; step < 2; ++step) detector->detect(scene.mesh.vertices, scene.x1);
  return (status_bytes("VmHWM:") - resident_before) / static_cast<double>(mesh.num_faces());
}

// The timed steps of one thread count.
struct Timings {
  std::vector<double> refit, traversal, radial, low, ccd, total, floor;
  DetectionStats stats;
};

// One row per thread count of `options`, timed in rounds: each round runs one step on each
// thread count in turn, so that the machine's drifts in speed fall on all of them alike
// and the ratio of two thread counts within a round is a paired figure.
std::vector<ScaleRow> measure(const std::string& name, Index target, const ScaleScene& scene,
                              const ScaleOptions& options) {
  const std::size_t configs = options.threads.size();
  std::vector<ScaleRow> rows(configs);
  for (std::size_t i = 0; i < configs; ++i) {
    rows[i].scene = name;
    rows[i].threads = options.threads[i];
    rows[i].triangles = static_cast<Index>(scene.mesh.faces.rows());
    rows[i].bytes_per_triangle = options.memory_probe
                                     ? options.memory_probe(name, target, options.threads[i])
                                     : bytes_per_triangle(scene, options.threads[i]);
  }
  const TriangleMesh mesh(static_cast<Index>(scene.mesh.vertices.rows()), scene.mesh.faces);
  std::vector<std::unique_ptr<SelfCollisionDetector>> detectors;
  std::vector<std::unique_ptr<tbb::task_arena>> arenas;
  std::vector<Aabb> boxes(static_cast<std::size_t>(mesh.num_faces()));
  for (const int threads : options.threads) {
    detectors.push_back(paper_detector(mesh, scene, threads));
    detectors.back()->detect(scene.mesh.vertices, scene.x1);  // warm-up: buffers reach their size
    arenas.push_back(std::make_unique<tbb::task_arena>(threads));
    floor_ms(scene.mesh.faces, scene.mesh.vertices, scene.x1, boxes, *arenas.back());
  }
  std::vector<Timings> timings(configs);
  std::vector<std::vector<double>> round_speedups(configs);
  // Every thread count gets at least min_seconds (the fastest gets there last).
  double least_ms = 0;
  for (std::size_t rounds = 0; more_runs(options, rounds, least_ms); ++rounds) {
    for (std::size_t i = 0; i < configs; ++i) {
      Timings& t = timings[i];
      t.stats = detectors[i]->detect(scene.mesh.vertices, scene.x1).stats;
      t.refit.push_back(t.stats.refit_ms), t.traversal.push_back(t.stats.traversal_ms);
      t.radial.push_back(t.stats.radial_view_ms);
      t.low.push_back(t.stats.pair_generation_ms), t.ccd.push_back(t.stats.ccd_ms);
      t.total.push_back(t.stats.total_ms);
      t.floor.push_back(
          floor_ms(scene.mesh.faces, scene.mesh.vertices, scene.x1, boxes, *arenas[i]));
    }
    least_ms = sum(timings[0].total);
    for (std::size_t i = 0; i < configs; ++i) {
      round_speedups[i].push_back(timings[0].total.back() / timings[i].total.back());
      least_ms = std::min(least_ms, sum(timings[i].total));
    }
  }
  for (std::size_t i = 0; i < configs; ++i) {
    const Timings& t = timings[i];
    ScaleRow& row = rows[i];
    row.refit_ms = median(t.refit), row.traversal_ms = median(t.traversal);
    row.radial_view_ms = median(t.radial);
    row.low_level_ms = median(t.low), row.ccd_ms = median(t.ccd), row.total_ms = median(t.total);
    row.floor_ms = median(t.floor);
    row.boxes_refitted = t.stats.boxes_refitted != 0;
    row.speedup = median(round_speedups[i]);
    row.ctps = t.stats.candidate_triangle_pairs;
    row.vf = t.stats.vf_tested, row.ee = t.stats.ee_tested;
    row.collisions = t.stats.vf_colliding + t.stats.ee_colliding;
    row.peak_mib = status_bytes("VmHWM:") / (1024.0 * 1024.0);
  }
  return rows;
}

std::string with_commas(std::int64_t value) {
  std::string digits = std::to_string(value < 0 ? -value : value), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return value < 0 ? "-" + out : out;
}

}  // namespace

double scale_bytes_per_triangle(const std::string& scene, Index target_triangles, int threads) {
  const ScaleScene measured = make_scene(scene, target_triangles);
  // What a process pays once, whatever the mesh (worker threads and their stacks, the
  // allocator's per-thread arenas), is paid first on a small mesh, so that the figure is
  // what grows with the mesh.
  bytes_per_triangle(make_scene(scene, 200), threads);
  return bytes_per_triangle(measured, threads);
}

std::vector<std::string> scale_scene_names() {
  return {"cloth", "folded", "pleated", "sleeve"};
}

std::vector<ScaleRow> run_scale_benchmark(const ScaleOptions& options) {
  const std::vector<std::string> known = scale_scene_names();
  for (const std::string& name : options.scenes) {
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      throw InputError(
          fmt::format("unknown scale scene '{}' (expected cloth, folded, pleated, sleeve)", name));
    }
  }
  std::vector<Index> sizes;
  for (double t = options.min_triangles; t <= options.max_triangles * 1.0001;
       t *= std::sqrt(10.0)) {
    sizes.push_back(static_cast<Index>(std::lround(t)));
  }
  std::vector<ScaleRow> rows;
  for (const std::string& name : options.scenes) {
    for (Index target : sizes) {
      const ScaleScene scene = make_scene(name, target);
      if (options.progress) {
        options.progress(fmt::format("{} {} triangles", name, scene.mesh.faces.rows()));
      }
      for (ScaleRow& row : measure(name, target, scene, options)) rows.push_back(std::move(row));
    }
  }
  return rows;
}

std::string scale_csv(const std::vector<ScaleRow>& rows) {
  std::string csv =
      "scene,threads,triangles,floor_ms,refit_ms,traversal_ms,radial_view_ms,low_level_ms,ccd_ms,"
      "total_ms,speedup,ctps,vf,ee,collisions,pairs_per_collision,bytes_per_triangle,peak_mib,"
      "boxes_refitted\n";
  for (const ScaleRow& r : rows) {
    csv += fmt::format(
        "{},{},{},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},"
        "{},{},{},{},{:.3f},{:.1f},{:.1f},{:d}\n",
        r.scene, r.threads, r.triangles, r.floor_ms, r.refit_ms, r.traversal_ms, r.radial_view_ms,
        r.low_level_ms, r.ccd_ms, r.total_ms, r.speedup, r.ctps, r.vf, r.ee, r.collisions,
        r.pairs_per_collision(), r.bytes_per_triangle, r.peak_mib, r.boxes_refitted ? 1 : 0);
  }
  return csv;
}

std::string scale_markdown(const std::vector<ScaleRow>& rows) {
  std::string md =
      "| scene | threads | triangles | floor | refit | traversal | radial view | low level | "
      "exact CCD | total | speed-up | all but CCD | CTPs | to CCD | collisions | "
      "pairs/collision | B/triangle |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const ScaleRow& r : rows) {
    md += fmt::format(
        "| {} | {} | {} | {:.2f} | {:.2f}{} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | "
        "{:.2f}× | {:.2f} | {} | {} | {} | {:.2f} | {:.0f} |\n",
        r.scene, r.threads, with_commas(r.triangles), r.floor_ms, r.refit_ms,
        r.boxes_refitted ? "" : "*", r.traversal_ms, r.radial_view_ms, r.low_level_ms, r.ccd_ms,
        r.total_ms, r.speedup, r.total_ms - r.ccd_ms, with_commas(r.ctps), with_commas(r.vf + r.ee),
        with_commas(r.collisions), r.pairs_per_collision(), r.bytes_per_triangle);
  }
  return md;
}

LinePlot scale_plot(const std::vector<ScaleRow>& rows) {
  LinePlot plot;
  plot.title = "Detection time per step (preset paper)";
  plot.x_label = "triangles";
  plot.y_label = "milliseconds";
  plot.log_x = plot.log_y = true;
  std::vector<std::pair<std::string, int>> series;
  for (const ScaleRow& r : rows) {
    if (std::find(series.begin(), series.end(), std::pair{r.scene, r.threads}) == series.end()) {
      series.emplace_back(r.scene, r.threads);
    }
  }
  for (const auto& [scene, threads] : series) {
    PlotSeries total, floor;
    total.name = fmt::format("{} {}T step", scene, threads);
    floor.name = fmt::format("{} {}T floor", scene, threads);
    for (const ScaleRow& r : rows) {
      if (r.scene != scene || r.threads != threads) continue;
      total.x.push_back(r.triangles), total.y.push_back(r.total_ms);
      floor.x.push_back(r.triangles), floor.y.push_back(r.floor_ms);
    }
    plot.series.push_back(std::move(total));
    plot.series.push_back(std::move(floor));
  }
  return plot;
}

}  // namespace tailor
