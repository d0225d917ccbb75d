#include "bench/scale_benchmark.hpp"

#include <fmt/format.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <numbers>

#include "tailor/bvh/mesh_bvh.hpp"
#include "tailor/detection/self_collision_detector.hpp"
#include "tailor/mesh/procedural_meshes.hpp"

namespace tailor {
namespace {

double peak_resident_mib() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  }
  return 0;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

struct ScaleScene {
  MeshData mesh;
  Positions x1;
  std::vector<std::vector<Index>> section_loops;
};

ScaleScene crumpling_cloth_scene(Index triangles) {
  const int cells = std::max(2, static_cast<int>(std::lround(std::sqrt(triangles / 2.0))));
  ScaleScene scene;
  scene.mesh = make_grid(cells, cells, 1.0, 1.0);
  const Positions rest = scene.mesh.vertices;
  scene.mesh.vertices = crumpling_cloth(rest, 0.5);
  scene.x1 = crumpling_cloth(rest, 0.51);
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

}  // namespace

std::vector<ScaleRow> run_scale_benchmark(const ScaleOptions& options) {
  using Clock = std::chrono::steady_clock;
  std::vector<ScaleRow> rows;
  std::vector<Index> sizes;
  for (double t = 1000; t <= options.max_triangles * 1.0001; t *= std::sqrt(10.0)) {
    sizes.push_back(static_cast<Index>(std::lround(t)));
  }
  for (const std::string name : {"cloth", "sleeve"}) {
    for (Index target : sizes) {
      const ScaleScene scene =
          name == "cloth" ? crumpling_cloth_scene(target) : sleeve_scene(target);
      const TriangleMesh mesh(static_cast<Index>(scene.mesh.vertices.rows()), scene.mesh.faces);
      for (int threads : {1, 2}) {
        if (options.progress) {
          options.progress(fmt::format("{} {} triangles, {} thread{}", name, mesh.num_faces(),
                                       threads, threads > 1 ? "s" : ""));
        }
        ScaleRow row;
        row.scene = name;
        row.threads = threads;
        row.triangles = mesh.num_faces();
        DetectionConfig config = DetectionConfig::preset("paper");
        config.threads = threads;
        SelfCollisionDetector detector(mesh, scene.mesh.vertices, config, scene.section_loops);
        detector.detect(scene.mesh.vertices, scene.x1);  // warm-up
        std::vector<double> refit, traversal, low, ccd, total, floor;
        DetectionStats stats;
        for (int r = 0; r < options.repetitions; ++r) {
          stats = detector.detect(scene.mesh.vertices, scene.x1).stats;
          refit.push_back(stats.refit_ms), traversal.push_back(stats.traversal_ms);
          low.push_back(stats.pair_generation_ms), ccd.push_back(stats.ccd_ms);
          total.push_back(stats.total_ms);
        }
        MeshBvh bvh(mesh, scene.mesh.vertices);
        tbb::task_arena arena(threads);
        for (int r = 0; r < options.repetitions; ++r) {
          const auto start = Clock::now();
          arena.execute([&] { bvh.refit(scene.mesh.vertices, scene.x1, true); });
          floor.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        }
        row.floor_ms = median(floor);
        row.refit_ms = median(refit), row.traversal_ms = median(traversal);
        row.low_level_ms = median(low), row.ccd_ms = median(ccd), row.total_ms = median(total);
        row.ctps = stats.candidate_triangle_pairs;
        row.vf = stats.vf_tested, row.ee = stats.ee_tested;
        row.collisions = stats.vf_colliding + stats.ee_colliding;
        row.peak_mib = peak_resident_mib();
        rows.push_back(row);
      }
    }
  }
  return rows;
}

std::string scale_csv(const std::vector<ScaleRow>& rows) {
  std::string csv =
      "scene,threads,triangles,floor_ms,refit_ms,traversal_ms,low_level_ms,ccd_ms,total_ms,"
      "ctps,vf,ee,collisions,peak_mib\n";
  for (const ScaleRow& r : rows) {
    csv += fmt::format("{},{},{},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{},{},{},{},{:.1f}\n",
                       r.scene, r.threads, r.triangles, r.floor_ms, r.refit_ms, r.traversal_ms,
                       r.low_level_ms, r.ccd_ms, r.total_ms, r.ctps, r.vf, r.ee, r.collisions,
                       r.peak_mib);
  }
  return csv;
}

LinePlot scale_plot(const std::vector<ScaleRow>& rows) {
  LinePlot plot;
  plot.title = "Detection time per step (preset paper)";
  plot.x_label = "triangles";
  plot.y_label = "milliseconds";
  plot.log_x = plot.log_y = true;
  for (const std::string scene : {"cloth", "sleeve"}) {
    for (int threads : {1, 2}) {
      PlotSeries total, floor;
      total.name = fmt::format("{} {}T step", scene, threads);
      floor.name = fmt::format("{} {}T refit", scene, threads);
      for (const ScaleRow& r : rows) {
        if (r.scene != scene || r.threads != threads) continue;
        total.x.push_back(r.triangles), total.y.push_back(r.total_ms);
        floor.x.push_back(r.triangles), floor.y.push_back(r.floor_ms);
      }
      plot.series.push_back(std::move(total));
      plot.series.push_back(std::move(floor));
    }
  }
  return plot;
}

}  // namespace tailor
