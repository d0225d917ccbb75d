/// @file
/// `tailor.Mesh`: the connectivity of a triangle mesh (tailor::TriangleMesh).

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>

#include "arrays.hpp"
#include "bindings.hpp"
#include "tailor/mesh/triangle_mesh.hpp"

namespace tailor::python {
namespace {

std::shared_ptr<TriangleMesh> make_mesh(py::handle faces_object,
                                        std::optional<Index> num_vertices) {
  FaceArray faces = to_faces(faces_object, "faces");
  const Index vertices =
      num_vertices ? *num_vertices : (faces.size() > 0 ? faces.maxCoeff() + 1 : 0);
  return std::make_shared<TriangleMesh>(vertices, std::move(faces));
}

py::array index_array(const std::vector<Index>& ids) {
  return py::array_t<Index>(static_cast<py::ssize_t>(ids.size()), ids.data());
}

}  // namespace

void bind_mesh(py::module_& m) {
  py::class_<TriangleMesh, std::shared_ptr<TriangleMesh>>(
      m, "Mesh",
      "Fixed connectivity of a triangle mesh: edges, adjacency, boundary loops, components.\n\n"
      "Edges are the unique pairs (a, b), a < b, sorted by (b, a), as in the reference data.")
      .def(py::init(&make_mesh), py::arg("faces"), py::kw_only(),
           py::arg("num_vertices") = py::none(),
           "Builds the connectivity of `faces` ((n, 3) vertex ids). `num_vertices` defaults to "
           "the largest id + 1. Raises InputError (a ValueError) on an id out of range or a "
           "face that repeats a vertex.")
      .def_property_readonly("num_vertices", &TriangleMesh::num_vertices)
      .def_property_readonly("num_faces", &TriangleMesh::num_faces)
      .def_property_readonly("num_edges", &TriangleMesh::num_edges)
      .def_property_readonly(
          "faces",
          [](py::object self) {
            auto& mesh = self.cast<TriangleMesh&>();
            return view_of(const_cast<FaceArray&>(mesh.faces()), self, false);
          },
          "(n, 3) int32 vertex ids: a read-only view of the mesh's own array (no copy).")
      .def_property_readonly(
          "edges",
          [](py::object self) {
            auto& mesh = self.cast<TriangleMesh&>();
            return view_of(const_cast<EdgeArray&>(mesh.edges()), self, false);
          },
          "(e, 2) int32 vertex ids (a < b), sorted by (b, a): a read-only view (no copy).")
      .def("find_edge", &TriangleMesh::find_edge, py::arg("a"), py::arg("b"),
           "Id of the edge joining vertices a and b (either order), or -1.")
      .def_property_readonly("num_boundary_loops", &TriangleMesh::num_boundary_loops)
      .def(
          "boundary_loop",
          [](const TriangleMesh& mesh, Index i) {
            if (i < 0 || i >= mesh.num_boundary_loops()) {
              throw py::index_error(fmt::format("boundary loop {} out of range [0, {})", i,
                                                mesh.num_boundary_loops()));
            }
            const auto loop = mesh.boundary_loop(i);
            return py::array_t<Index>(static_cast<py::ssize_t>(loop.size()), loop.data());
          },
          py::arg("i"), "Vertex ids of boundary loop i, in walking order.")
      .def_property_readonly("num_components", &TriangleMesh::num_components)
      .def_property_readonly(
          "face_components",
          [](const TriangleMesh& mesh) { return index_array(mesh.face_components()); },
          "Connected-component id of each face.")
      .def_property_readonly("non_manifold_edges",
                             [](const TriangleMesh& mesh) {
                               return index_array(mesh.validation().non_manifold_edges);
                             })
      .def_property_readonly("unreferenced_vertices",
                             [](const TriangleMesh& mesh) {
                               return index_array(mesh.validation().unreferenced_vertices);
                             })
      .def("__repr__", [](const TriangleMesh& mesh) {
        return fmt::format("tailor.Mesh({} vertices, {} faces, {} edges)", mesh.num_vertices(),
                           mesh.num_faces(), mesh.num_edges());
      });
}

}  // namespace tailor::python
