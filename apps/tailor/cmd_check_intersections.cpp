/// @file
/// `tailor check-intersections MESH [OBSTACLE]`: exact static check that a mesh does not
/// intersect itself (nor the obstacle mesh). Exit code 1 when anything intersects.

#include <fmt/format.h>

#include <memory>
#include <string>

#include "command.hpp"
#include "tailor/detection/intersection_check.hpp"
#include "tailor/io/mesh_io.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor::cli {
namespace {

int run_check_intersections(const std::string& mesh_file, const std::string& obstacle_file,
                            std::size_t max_pairs) {
  const MeshData cloth_data = read_mesh(mesh_file);
  const TriangleMesh cloth(static_cast<Index>(cloth_data.vertices.rows()), cloth_data.faces);
  std::unique_ptr<MeshData> obstacle_data;
  std::unique_ptr<TriangleMesh> obstacle;
  if (!obstacle_file.empty()) {
    obstacle_data = std::make_unique<MeshData>(read_mesh(obstacle_file));
    obstacle = std::make_unique<TriangleMesh>(static_cast<Index>(obstacle_data->vertices.rows()),
                                              obstacle_data->faces);
  }
  const IntersectionReport report =
      check_intersections(cloth, cloth_data.vertices, obstacle.get(),
                          obstacle_data ? &obstacle_data->vertices : nullptr, max_pairs);

  fmt::print("mesh:                       {} ({} faces)\n", mesh_file, cloth.num_faces());
  fmt::print("candidate face pairs:       {}\n", report.self_candidate_pairs);
  fmt::print("self intersections:         {}\n", report.self_intersections);
  fmt::print("adjacent intersections:     {}\n", report.adjacent_intersections);
  fmt::print("degenerate faces:           {}\n", report.degenerate_faces);
  fmt::print("undecided adjacent pairs:   {}\n", report.undecided_adjacent_pairs);
  for (const auto& [f, g] : report.self_pairs) fmt::print("  faces {} {}\n", f, g);
  if (obstacle) {
    fmt::print("obstacle:                   {} ({} faces)\n", obstacle_file, obstacle->num_faces());
    fmt::print("obstacle candidate pairs:   {}\n", report.obstacle_candidate_pairs);
    fmt::print("obstacle intersections:     {}\n", report.obstacle_intersections);
    for (const auto& [f, g] : report.obstacle_pairs) {
      fmt::print("  face {} obstacle face {}\n", f, g);
    }
  }
  fmt::print("result:                     {}\n",
             report.intersection_free() ? "intersection-free" : "INTERSECTING");
  return report.intersection_free() ? kSuccess : kFailure;
}

const CommandRegistration check_intersections_registration{
    "check-intersections", [](CLI::App& app) -> std::function<int()> {
      CLI::App* command = app.add_subcommand(
          "check-intersections",
          "Exact static check for self-intersections (and intersections with an obstacle)");
      auto mesh = std::make_shared<std::string>();
      auto obstacle = std::make_shared<std::string>();
      auto max_pairs = std::make_shared<std::size_t>(10);
      command->add_option("mesh", *mesh, "Mesh file (.obj or .ply)")->required();
      command->add_option("obstacle", *obstacle, "Obstacle mesh file (.obj or .ply)");
      command->add_option("--max-pairs", *max_pairs, "Intersecting pairs to list")
          ->check(CLI::Range(0, 1'000'000'000))
          ->capture_default_str();
      return [mesh, obstacle, max_pairs] {
        return run_check_intersections(*mesh, *obstacle, *max_pairs);
      };
    }};

}  // namespace
}  // namespace tailor::cli
