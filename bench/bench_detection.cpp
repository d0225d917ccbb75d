// Per-stage cost of the self-collision detector on a procedurally crumpling cloth, from
// 10K to 1M triangles, on the contact-heavy folded cloth (~1 collision per triangle), on
// the dense pleated cloth (the contact density of real steps) and on cloth-ball's real
// step, 1 and 2 threads; the refit of boxes and cones alone, for comparison; what the
// detector builds once per mesh, on cloth-ball.

#include <benchmark/benchmark.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <map>
#include <memory>
#include <string>

#include "tailor/bvh/aabb.hpp"
#include "tailor/bvh/mesh_bvh.hpp"
#include "tailor/candidates/isolated_set.hpp"
#include "tailor/candidates/primitive_pair_generator.hpp"
#include "tailor/culling/contour_test.hpp"
#include "tailor/culling/node_contours.hpp"
#include "tailor/detection/self_collision_detector.hpp"
#include "tailor/io/mesh_io.hpp"
#include "tailor/mesh/procedural_meshes.hpp"
#include "tailor/mesh/procedural_steps.hpp"

namespace tailor {
namespace {

struct Scene {
  MeshData grid;
  std::unique_ptr<TriangleMesh> mesh;
  Positions x0, x1;
};

// The cloth crumpling at time `t` over a step of 0.01: t = 0 is flat (no contact).
const Scene& scene(int cells, double t) {
  static std::map<std::pair<int, double>, Scene> cache;
  auto [it, inserted] = cache.try_emplace({cells, t});
  Scene& s = it->second;
  if (inserted) {
    s.grid = make_grid(cells, cells, 1.0, 1.0);
    s.mesh =
        std::make_unique<TriangleMesh>(static_cast<Index>(s.grid.vertices.rows()), s.grid.faces);
    s.x0 = crumpling_cloth(s.grid.vertices, t);
    s.x1 = crumpling_cloth(s.grid.vertices, t + 0.01);
  }
  return s;
}

void set_counters(benchmark::State& state, const DetectionStats& s, int faces) {
  state.counters["triangles"] = faces;
  state.counters["refit_ms"] = s.refit_ms;
  state.counters["traversal_ms"] = s.traversal_ms;
  state.counters["pairs_ms"] = s.pair_generation_ms;
  state.counters["ccd_ms"] = s.ccd_ms;
  state.counters["node_pairs"] = static_cast<double>(s.node_pairs_visited);
  state.counters["contour_tests"] = static_cast<double>(s.contour_tests);
  state.counters["cone_culls"] = static_cast<double>(s.nodes_culled_by_cones);
  state.counters["ctps"] = static_cast<double>(s.candidate_triangle_pairs);
  state.counters["vf"] = static_cast<double>(s.vf_tested);
  state.counters["ee"] = static_cast<double>(s.ee_tested);
  state.counters["collisions"] = static_cast<double>(s.vf_colliding + s.ee_colliding);
}

// The paper preset's detection of the step of `s` on `threads` threads, timed.
void detect_step(benchmark::State& state, const Scene& s, int threads) {
  DetectionConfig config = DetectionConfig::preset("paper");
  config.threads = threads;
  SelfCollisionDetector detector(*s.mesh, s.x0, config);
  DetectionStats last;
  for (auto _ : state) {
    DetectionResult result = detector.detect(s.x0, s.x1);
    benchmark::DoNotOptimize(result.collisions.vertex_face.data());
    benchmark::DoNotOptimize(result.collisions.edge_edge.data());
    last = result.stats;
  }
  set_counters(state, last, s.mesh->num_faces());
}

// Whole detection step; args: grid cells per side, threads, crumple time x100.
void BM_DetectStep(benchmark::State& state) {
  detect_step(state, scene(static_cast<int>(state.range(0)), state.range(2) / 100.0),
              static_cast<int>(state.range(1)));
}

// A procedural step of about `triangles` triangles (cached): the folded cloth on a sphere
// or the pleated cloth (the contact density of real dense steps such as cloth-ball).
enum class Procedural { folded, pleated };
const Scene& procedural_scene(Procedural kind, std::int64_t triangles) {
  static std::map<std::pair<Procedural, std::int64_t>, Scene> cache;
  auto [it, inserted] = cache.try_emplace({kind, triangles});
  Scene& s = it->second;
  if (inserted) {
    ProceduralStep step = kind == Procedural::folded ? make_folded_cloth_on_sphere(triangles)
                                                     : make_pleated_cloth(triangles);
    s.mesh = std::make_unique<TriangleMesh>(static_cast<Index>(step.x0.rows()), step.faces);
    s.x0 = std::move(step.x0);
    s.x1 = std::move(step.x1);
  }
  return s;
}

// The contact-heavy step; args: triangles, threads.
void BM_DetectFoldedStep(benchmark::State& state) {
  detect_step(state, procedural_scene(Procedural::folded, state.range(0)),
              static_cast<int>(state.range(1)));
}

// The dense-contact step (some 35 candidate triangle pairs and 2 collisions per
// triangle); args: triangles, threads.
void BM_DetectPleatedStep(benchmark::State& state) {
  detect_step(state, procedural_scene(Procedural::pleated, state.range(0)),
              static_cast<int>(state.range(1)));
}

// cloth-ball's step 92 -> 93 (../shared/data/cloth-ball: 92,230 triangles, its faces in no
// spatial order), read once; nullptr (the benchmark skipped) when the data is not there.
const Scene* cloth_ball(benchmark::State& state) {
  static Scene s;
  if (!s.mesh) {
    const std::string dir = std::string(TAILOR_DATA_DIR) + "/cloth-ball/frames/";
    try {
      MeshData m0 = read_mesh(dir + "cloth_ball92.ply");
      MeshData m1 = read_mesh(dir + "cloth_ball93.ply");
      s.mesh = std::make_unique<TriangleMesh>(static_cast<Index>(m0.vertices.rows()), m0.faces);
      s.x0 = std::move(m0.vertices);
      s.x1 = std::move(m1.vertices);
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());  // the reference data is not beside the repository
      return nullptr;
    }
  }
  return &s;
}

// cloth-ball's step (113,854 colliding pairs), the detector built once; arg: threads.
void BM_DetectClothBallStep(benchmark::State& state) {
  if (const Scene* s = cloth_ball(state)) detect_step(state, *s, static_cast<int>(state.range(0)));
}

// What the detector builds once per mesh, on cloth-ball, part by part (0 the BVH, 1 its
// nodes' contours, 2 the isolated set, 3 the pair generator's feature assignment, 4 the
// whole detector, paper preset); args: part, threads.
void BM_ClothBallBuild(benchmark::State& state) {
  const Scene* s = cloth_ball(state);
  if (s == nullptr) return;
  const int part = static_cast<int>(state.range(0));
  tbb::task_arena arena(static_cast<int>(state.range(1)));
  const MeshBvh bvh = arena.execute([&] { return MeshBvh(*s->mesh, s->x0); });
  DetectionConfig config = DetectionConfig::preset("paper");
  config.threads = static_cast<int>(state.range(1));
  for (auto _ : state) {
    arena.execute([&] {
      switch (part) {
        case 0:
          benchmark::DoNotOptimize(MeshBvh(*s->mesh, s->x0));
          break;
        case 1:
          benchmark::DoNotOptimize(NodeContours(*s->mesh, bvh));
          break;
        case 2:
          benchmark::DoNotOptimize(IsolatedSet::build(*s->mesh));
          break;
        case 3:
          benchmark::DoNotOptimize(PrimitivePairGenerator(*s->mesh));
          break;
        default:
          benchmark::DoNotOptimize(SelfCollisionDetector(*s->mesh, s->x0, config));
      }
    });
  }
  static const char* names[] = {"bvh", "contours", "isolated set", "generator", "detector"};
  state.SetLabel(names[std::min(part, 4)]);
}

// Refitting swept boxes and direction masks, boxes only, or masks only (what a step whose
// root stays certified refits).
enum class RefitKind { boxes_and_directions, boxes, directions };
void refit(benchmark::State& state, RefitKind kind) {
  const Scene& s = scene(static_cast<int>(state.range(0)), state.range(2) / 100.0);
  MeshBvh bvh(*s.mesh, s.x0);
  tbb::task_arena arena(static_cast<int>(state.range(1)));
  for (auto _ : state) {
    arena.execute([&] {
      if (kind == RefitKind::directions) {
        bvh.refit_directions(s.x0, s.x1);
      } else {
        bvh.refit(s.x0, s.x1, kind == RefitKind::boxes_and_directions);
      }
    });
    benchmark::DoNotOptimize(bvh.start_box(0));
    benchmark::DoNotOptimize(bvh.direction_mask(0));
  }
  state.counters["triangles"] = s.mesh->num_faces();
}
void BM_RefitOnly(benchmark::State& state) {
  refit(state, RefitKind::boxes_and_directions);
}
void BM_RefitBoxesOnly(benchmark::State& state) {
  refit(state, RefitKind::boxes);
}
void BM_RefitDirectionsOnly(benchmark::State& state) {
  refit(state, RefitKind::directions);
}

// The floor the refit is measured against (as in `tailor bench scale`): every face's
// swept box (double) from x0 and x1, in parallel, stored.
void BM_SweptBoxFloor(benchmark::State& state) {
  const Scene& s = scene(static_cast<int>(state.range(0)), state.range(2) / 100.0);
  const FaceArray& faces = s.mesh->faces();
  std::vector<Aabb> boxes(static_cast<std::size_t>(faces.rows()));
  tbb::task_arena arena(static_cast<int>(state.range(1)));
  for (auto _ : state) {
    arena.execute([&] { swept_face_boxes(faces, s.x0, s.x1, boxes); });
    benchmark::DoNotOptimize(boxes.data());
  }
  state.counters["triangles"] = s.mesh->num_faces();
}

// The contour test of the crumpling cloth's root (its boundary: 4 x cells edges), the whole
// traversal of that step; args: grid cells per side, threads.
void BM_ContourTestOfRoot(benchmark::State& state) {
  const Scene& s = scene(static_cast<int>(state.range(0)), 0.5);
  MeshBvh bvh(*s.mesh, s.x0);
  bvh.refit(s.x0, s.x1, true);
  const NodeContours contours(*s.mesh, bvh);
  const std::optional<Vec3> axis = bvh.acute_axis(0);
  if (!axis || !contours.has_single_loop(0)) {
    state.SkipWithError("the root has no cone axis or no single boundary loop");
    return;
  }
  tbb::task_arena arena(static_cast<int>(state.range(1)));
  bool simple = false;
  for (auto _ : state) {
    arena.execute([&] { simple = contour_stays_simple(contours.loop(0), s.x0, s.x1, *axis); });
    benchmark::DoNotOptimize(simple);
  }
  state.counters["edges"] = static_cast<double>(contours.loop(0).size());
  state.counters["simple"] = simple;
}

// The direction-mask kernel alone on batches in cache: 1,024 batches of 12 triangles of
// the crumpling cloth's 10K-triangle step (as the refit forms them: consecutive faces).
void BM_DirectionMaskKernel(benchmark::State& state) {
  const Scene& s = scene(71, 0.5);
  const FaceArray& faces = s.mesh->faces();
  std::vector<MovingTriangleBatch> batches(1024);
  for (std::size_t b = 0; b < batches.size(); ++b) {
    for (int i = 0; i < 12; ++i) {
      const Index f = static_cast<Index>((12 * b + i) % faces.rows());
      const auto row = [&](const Positions& x, int k) { return x.row(faces(f, k)).data(); };
      batches[b].add(row(s.x0, 0), row(s.x0, 1), row(s.x0, 2), row(s.x1, 0), row(s.x1, 1),
                     row(s.x1, 2));
    }
    batches[b].pad();
  }
  for (auto _ : state) {
    DirectionMask all = 0;
    for (const MovingTriangleBatch& batch : batches) all |= direction_mask(batch);
    benchmark::DoNotOptimize(all);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * 12 * 1024);
}

void sizes(benchmark::internal::Benchmark* b) {
  for (int cells : {71, 224, 708}) {  // ~10K, 100K, 1M triangles
    for (int threads : {1, 2}) {
      for (int crumple : {0, 50}) b->Args({cells, threads, crumple});
    }
  }
  b->ArgNames({"cells", "threads", "crumple"})->Unit(benchmark::kMillisecond)->UseRealTime();
}

BENCHMARK(BM_DetectStep)->Apply(sizes);
BENCHMARK(BM_DetectFoldedStep)
    ->ArgsProduct({{10'000, 100'000}, {1, 2}})
    ->ArgNames({"triangles", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_DetectPleatedStep)
    ->ArgsProduct({{100'000, 1'000'000}, {1, 2}})
    ->ArgNames({"triangles", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_DetectClothBallStep)
    ->Arg(1)
    ->Arg(2)
    ->ArgName("threads")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_ClothBallBuild)
    ->ArgsProduct({{0, 1, 2, 3, 4}, {1, 2}})
    ->ArgNames({"part", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_RefitOnly)->Apply(sizes);
BENCHMARK(BM_RefitBoxesOnly)->Apply(sizes);
BENCHMARK(BM_RefitDirectionsOnly)->Apply(sizes);
BENCHMARK(BM_SweptBoxFloor)->Apply(sizes);
BENCHMARK(BM_DirectionMaskKernel);
BENCHMARK(BM_ContourTestOfRoot)
    ->ArgsProduct({{224, 708}, {1, 2}})
    ->ArgNames({"cells", "threads"})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

}  // namespace
}  // namespace tailor

BENCHMARK_MAIN();
