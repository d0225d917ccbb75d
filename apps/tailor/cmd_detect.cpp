/// @file
/// `tailor detect MESH_T0 MESH_T1`: the self-collisions of one step.

#include <fmt/format.h>
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>

#include <exception>
#include <fstream>
#include <nlohmann/json.hpp>

#include "command.hpp"
#include "detection_options.hpp"
#include "tailor/ccd/query_writer.hpp"
#include "tailor/detection/brute_force.hpp"
#include "tailor/detection/ccd_query_export.hpp"
#include "tailor/detection/collision_free_step.hpp"
#include "tailor/detection/self_collision_detector.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/geometry/stopwatch.hpp"
#include "tailor/io/mesh_io.hpp"
#include "tailor/io/observer_loops.hpp"

namespace tailor::cli {
namespace {

struct DetectArgs {
  std::string mesh_t0, mesh_t1, json_path, observers_path, dump_prefix;
  bool brute_force = false;
  DetectionOptions detection;
};

nlohmann::json collisions_json(const CollisionSet& collisions) {
  nlohmann::json vf = nlohmann::json::array(), ee = nlohmann::json::array();
  for (const auto& c : collisions.vertex_face) vf.push_back({c.vertex, c.face, c.toi});
  for (const auto& c : collisions.edge_edge) ee.push_back({c.a0, c.a1, c.b0, c.b1, c.toi});
  return {{"vertex_face", vf}, {"edge_edge", ee}};
}

void print_stats(const DetectionStats& s) {
  fmt::print(
      "high level : {} node pairs visited and {} leaf buckets, {} nodes culled by cones "
      "({} contour tests, {} failed), {} CTPs\n",
      s.node_pairs_visited, s.leaf_buckets, s.nodes_culled_by_cones, s.contour_tests,
      s.contour_tests_failed, s.candidate_triangle_pairs);
  fmt::print(
      "radial view: {} CTPs culled; {} clusters classified, {} certified; triangles facing {} / "
      "away {} / undetermined {}\n",
      s.radial_pairs_culled, s.clusters_classified, s.clusters_certified, s.radial_positive,
      s.radial_negative, s.radial_undetermined);
  fmt::print("triangles  : {} CTPs separated by a triangle's plane, {} kept apart by a direction\n",
             s.triangle_pairs_separated, s.triangle_pairs_apart);
  fmt::print("isolated   : {} VF, {} EE pairs\n", s.isolated_vf_pairs, s.isolated_ee_pairs);
  fmt::print("low level  :        {:>10} {:>10}\n", "VF", "EE");
  fmt::print("  generated         {:>10} {:>10}\n", s.vf_generated, s.ee_generated);
  fmt::print("  after boxes       {:>10} {:>10}\n", s.vf_after_boxes, s.ee_after_boxes);
  fmt::print("  after filter      {:>10} {:>10}\n", s.vf_after_filter, s.ee_after_filter);
  fmt::print("  after projection  {:>10} {:>10}\n", s.vf_after_projection, s.ee_after_projection);
  fmt::print("  exact CCD         {:>10} {:>10}  ({} decided by the exact path)\n", s.vf_tested,
             s.ee_tested, s.ccd_exact_fallbacks);
  fmt::print("  colliding         {:>10} {:>10}\n", s.vf_colliding, s.ee_colliding);
  fmt::print(
      "time (ms)  : refit {:.3f}, traversal {:.3f}, radial view {:.3f}, pair generation {:.3f}, "
      "exact CCD {:.3f}, total {:.3f}\n",
      s.refit_ms, s.traversal_ms, s.radial_view_ms, s.pair_generation_ms, s.ccd_ms, s.total_ms);
}

// The queries the detector sent to the exact CCD, written as query CSVs (`PREFIXvf.csv`,
// `PREFIXee.csv`) for benchmarks and ccd-check.
void dump_queries(const std::string& prefix, const TriangleMesh& mesh, const Positions& x0,
                  const Positions& x1, const DetectionConfig& config,
                  const std::vector<TrianglePair>& ctps) {
  const StepCcdQueries queries = step_ccd_queries(mesh, x0, x1, config, ctps);
  write_ccd_queries(prefix + "vf.csv", queries.vertex_face);
  write_ccd_queries(prefix + "ee.csv", queries.edge_edge);
  fmt::print("dumped     : {} VF queries to {}vf.csv, {} EE queries to {}ee.csv\n",
             queries.vertex_face.size(), prefix, queries.edge_edge.size(), prefix);
}

// Both frames, read side by side (in the caller's arena). Errors as if read one after the
// other: the first frame's first.
std::pair<MeshData, MeshData> read_frames(const std::string& path_t0, const std::string& path_t1) {
  MeshData t0, t1;
  std::exception_ptr error_t0, error_t1;
  const auto read = [](const std::string& path, MeshData& data, std::exception_ptr& error) {
    try {
      data = read_mesh(path);
    } catch (...) {
      error = std::current_exception();
    }
  };
  tbb::parallel_invoke([&] { read(path_t0, t0, error_t0); }, [&] { read(path_t1, t1, error_t1); });
  if (error_t0) std::rethrow_exception(error_t0);
  if (error_t1) std::rethrow_exception(error_t1);
  return {std::move(t0), std::move(t1)};
}

int run_detect(const DetectArgs& args) {
  // Reading and the mesh's connectivity run on the threads the detection may use.
  const int threads = args.detection.config().threads;
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  auto stage = SteadyClock::now();
  auto [t0, t1] = arena.execute([&] { return read_frames(args.mesh_t0, args.mesh_t1); });
  if (t0.vertices.rows() != t1.vertices.rows() || t0.faces != t1.faces) {
    throw InputError(fmt::format(
        "{} and {} do not have the same topology ({} vs {} vertices, "
        "{} vs {} faces{})",
        args.mesh_t0, args.mesh_t1, t0.vertices.rows(), t1.vertices.rows(), t0.faces.rows(),
        t1.faces.rows(), t0.faces.rows() == t1.faces.rows() ? ", different faces" : ""));
  }
  // The topology keeps the faces: no other copy is needed.
  t1.faces.resize(0, 3);
  const double read_ms = milliseconds_since(stage);
  stage = SteadyClock::now();
  const TriangleMesh mesh = arena.execute(
      [&] { return TriangleMesh(static_cast<Index>(t0.vertices.rows()), std::move(t0.faces)); });
  const double mesh_ms = milliseconds_since(stage);
  fmt::print("mesh       : {} vertices, {} faces, {} edges\n", mesh.num_vertices(),
             mesh.num_faces(), mesh.num_edges());

  nlohmann::json out;
  CollisionSet collisions;
  if (args.brute_force) {
    collisions = brute_force_self_collisions(mesh, t0.vertices, t1.vertices);
    fmt::print("method     : brute force\n");
  } else {
    DetectionConfig config = args.detection.config();
    if (!args.dump_prefix.empty()) config.keep_candidate_pairs = true;
    std::vector<std::vector<Index>> loops;
    if (!args.observers_path.empty()) {
      loops = read_observer_loops(args.observers_path, mesh.num_vertices());
    }
    stage = SteadyClock::now();
    SelfCollisionDetector detector(mesh, t0.vertices, config, std::move(loops));
    const double build_ms = milliseconds_since(stage);
    DetectionResult result = detector.detect(t0.vertices, t1.vertices);
    fmt::print("method     : {}\n", args.detection.method);
    // What a process pays before the step (a simulator builds the detector once).
    fmt::print("setup (ms) : read {:.3f}, mesh {:.3f}, detector build {:.3f}\n", read_ms, mesh_ms,
               build_ms);
    print_stats(result.stats);
    if (!args.dump_prefix.empty()) {
      dump_queries(args.dump_prefix, mesh, t0.vertices, t1.vertices, config,
                   result.candidate_triangle_pairs);
    }
    out["config"] = config;  // every setting (docs/settings.md)
    out["stats"] = result.stats;
    collisions = std::move(result.collisions);
  }
  fmt::print("collisions : {} vertex-face, {} edge-edge\n", collisions.vertex_face.size(),
             collisions.edge_edge.size());
  // The collision-free fraction of the step (collision_free_step).
  if (collisions.size() > 0) fmt::print("first toi  : {:.9g}\n", first_contact(collisions).alpha);
  if (!args.json_path.empty()) {
    out["collisions"] = collisions_json(collisions);
    std::ofstream file(args.json_path);
    if (!file) throw InputError(fmt::format("cannot write {}", args.json_path));
    file << out.dump(1) << "\n";
  }
  return kSuccess;
}

const CommandRegistration detect_registration{
    "detect", [](CLI::App& app) {
      auto args = std::make_shared<DetectArgs>();
      CLI::App* command =
          app.add_subcommand("detect", "Self-collisions of one step between two frames");
      command->add_option("MESH_T0", args->mesh_t0, "Mesh at the start of the step (OBJ or PLY)")
          ->required()
          ->check(CLI::ExistingFile);
      command->add_option("MESH_T1", args->mesh_t1, "Mesh at the end of the step (same topology)")
          ->required()
          ->check(CLI::ExistingFile);
      CLI::Option* brute = command->add_flag("--brute-force", args->brute_force,
                                             "Test every feature pair (the oracle)");
      command->add_option("--json", args->json_path,
                          "Write collisions, statistics and the settings used as JSON");
      command
          ->add_option("--observers", args->observers_path,
                       "Radial-view section loops: JSON {\"loops\": [[vertex ids], ...]}")
          ->check(CLI::ExistingFile);
      command
          ->add_option("--dump-queries", args->dump_prefix,
                       "Write the pairs sent to the exact CCD as query CSVs PREFIXvf.csv "
                       "and PREFIXee.csv (for ccd-check and benchmarks)")
          ->excludes(brute);
      args->detection.add_to(*command);
      return [args] { return run_detect(*args); };
    }};

}  // namespace
}  // namespace tailor::cli
