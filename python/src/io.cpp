/// @file
/// `tailor.read_mesh` and `tailor.write_mesh` (OBJ or PLY by extension).

#include <pybind11/stl/filesystem.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "errors.hpp"
#include "tailor/io/mesh_io.hpp"

namespace tailor::python {

void bind_io(py::module_& m) {
  m.def(
      "read_mesh",
      [](const std::filesystem::path& path) {
        MeshData data;
        with_file_errors(path, [&] {
          py::gil_scoped_release release;
          data = read_mesh(path);
        });
        // The arrays take over the reader's storage: no copy.
        return py::make_tuple(adopt(std::move(data.vertices)), adopt(std::move(data.faces)));
      },
      py::arg("path"),
      "Reads an OBJ or PLY file (by extension). Returns (vertices, faces): (n, 3) float64 and "
      "(m, 3) int32. Raises FileNotFoundError/OSError if it cannot be opened, InputError (a "
      "ValueError) naming the file and the problem on bad content.");
  m.def(
      "write_mesh",
      [](const std::filesystem::path& path, py::handle vertices, py::handle faces) {
        const Positions x = to_positions(vertices, "vertices");
        const FaceArray f = to_faces(faces, "faces");
        py::gil_scoped_release release;
        write_mesh(path, x, f);
      },
      py::arg("path"), py::arg("vertices"), py::arg("faces"),
      "Writes an OBJ or PLY (binary, float64) file, chosen by the extension. Raises "
      "InputError on an unknown extension, a bad face id, or a write error.");
}

}  // namespace tailor::python
