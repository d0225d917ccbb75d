/// @file
/// `tailor info MESH`: counts, topology and bounding box of a mesh file.

#include <fmt/format.h>

#include <memory>
#include <string>

#include "command.hpp"
#include "tailor/io/mesh_io.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor::cli {
namespace {

int run_info(const std::string& file) {
  const MeshData data = read_mesh(file);
  const Index nv = static_cast<Index>(data.vertices.rows());
  const TriangleMesh mesh(nv, data.faces);

  Index boundary_edges = 0;
  for (Index e = 0; e < mesh.num_edges(); ++e) boundary_edges += mesh.is_boundary_edge(e) ? 1 : 0;
  const auto& validation = mesh.validation();

  fmt::print("file:                  {}\n", file);
  fmt::print("vertices:              {}\n", nv);
  fmt::print("faces:                 {}\n", mesh.num_faces());
  fmt::print("edges:                 {}\n", mesh.num_edges());
  fmt::print("boundary edges:        {}\n", boundary_edges);
  fmt::print("boundary loops:        {}\n", mesh.num_boundary_loops());
  fmt::print("components:            {}\n", mesh.num_components());
  if (validation.is_manifold()) {
    fmt::print("manifold:              yes\n");
  } else {
    fmt::print("manifold:              no ({} non-manifold edges)\n",
               validation.non_manifold_edges.size());
  }
  fmt::print("unreferenced vertices: {}\n", validation.unreferenced_vertices.size());
  if (nv > 0) {
    const Vec3 lo = data.vertices.colwise().minCoeff().transpose();
    const Vec3 hi = data.vertices.colwise().maxCoeff().transpose();
    fmt::print("bounding box min:      {:.9g} {:.9g} {:.9g}\n", lo.x(), lo.y(), lo.z());
    fmt::print("bounding box max:      {:.9g} {:.9g} {:.9g}\n", hi.x(), hi.y(), hi.z());
    fmt::print("bounding box diagonal: {:.9g}\n", (hi - lo).norm());
  } else {
    fmt::print("bounding box:          empty\n");
  }
  return kSuccess;
}

const CommandRegistration info_registration{
    "info", [](CLI::App& app) -> std::function<int()> {
      CLI::App* command = app.add_subcommand("info", "Print counts, topology and bounds of a mesh");
      auto file = std::make_shared<std::string>();
      command->add_option("mesh", *file, "Mesh file (.obj or .ply)")->required();
      return [file] { return run_info(*file); };
    }};

}  // namespace
}  // namespace tailor::cli
