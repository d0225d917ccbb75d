/// @file
/// `tailor proximity MESH --thickness H`: every vertex-face and edge-edge pair of one
/// configuration within a distance H of each other (exact), for repulsion and barrier
/// methods.

#include <fmt/format.h>
#include <tbb/task_arena.h>

#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "command.hpp"
#include "tailor/detection/proximity_pairs.hpp"
#include "tailor/geometry/error.hpp"
#include "tailor/geometry/stopwatch.hpp"
#include "tailor/io/mesh_io.hpp"
#include "thread_limit.hpp"

namespace tailor::cli {
namespace {

struct ProximityArgs {
  std::string mesh, json_path;
  double thickness = -1;
  double diagonal_share = -1;
  int threads = 0;
};

int run_proximity(const ProximityArgs& args) {
  auto stage = SteadyClock::now();
  MeshData data = read_mesh(args.mesh);
  const TriangleMesh mesh(static_cast<Index>(data.vertices.rows()), std::move(data.faces));
  const double read_ms = milliseconds_since(stage);
  double h = args.thickness;
  if (args.diagonal_share >= 0) {
    const Vec3 diagonal =
        (data.vertices.colwise().maxCoeff() - data.vertices.colwise().minCoeff()).transpose();
    h = args.diagonal_share * diagonal.norm();
  }
  tbb::task_arena arena(args.threads > 0 ? args.threads : tbb::task_arena::automatic);
  stage = SteadyClock::now();
  const ProximityPairs pairs =
      arena.execute([&] { return proximity_pairs(mesh, data.vertices, h); });
  const double proximity_ms = milliseconds_since(stage);
  fmt::print("mesh       : {} vertices, {} faces, {} edges (read {:.3f} ms)\n", mesh.num_vertices(),
             mesh.num_faces(), mesh.num_edges(), read_ms);
  fmt::print("thickness  : {:.9g}\n", h);
  fmt::print("pairs      : {} vertex-face, {} edge-edge within the thickness ({:.3f} ms)\n",
             pairs.vertex_face.size(), pairs.edge_edge.size(), proximity_ms);
  if (!args.json_path.empty()) {
    nlohmann::json vf = nlohmann::json::array(), ee = nlohmann::json::array();
    for (const VertexFacePair& p : pairs.vertex_face) vf.push_back({p.vertex, p.face});
    for (const EdgeEdgePair& p : pairs.edge_edge) ee.push_back({p.edge_a, p.edge_b});
    const nlohmann::json out{{"thickness", h}, {"vertex_face", vf}, {"edge_edge", ee}};
    std::ofstream file(args.json_path);
    if (!file) throw InputError(fmt::format("cannot write {}", args.json_path));
    file << out.dump(1) << "\n";
  }
  return kSuccess;
}

const CommandRegistration proximity_registration{
    "proximity", [](CLI::App& app) {
      auto args = std::make_shared<ProximityArgs>();
      CLI::App* command = app.add_subcommand(
          "proximity", "Vertex-face and edge-edge pairs of one mesh within a thickness (exact)");
      command->add_option("MESH", args->mesh, "The configuration (OBJ or PLY)")
          ->required()
          ->check(CLI::ExistingFile);
      CLI::Option* absolute =
          command->add_option("--thickness", args->thickness, "The distance H (mesh units, >= 0)")
              ->check(CLI::Range(0.0, 1e300));
      CLI::Option* share = command
                               ->add_option("--thickness-share", args->diagonal_share,
                                            "H as a share of the bounding-box diagonal (e.g. 1e-3)")
                               ->check(CLI::Range(0.0, 1e6));
      absolute->excludes(share);
      command->add_option("--json", args->json_path, "Write the pairs as JSON");
      command->add_option("--threads", args->threads, "Worker threads (0: all cores)")
          ->check(thread_count_validator());
      return [args, absolute, share] {
        if (absolute->count() + share->count() == 0) {
          throw InputError("proximity: give --thickness H or --thickness-share S");
        }
        return run_proximity(*args);
      };
    }};

}  // namespace
}  // namespace tailor::cli
