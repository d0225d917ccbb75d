/// @file
/// OBJ files: reading (the mapped file through obj_parser.hpp) and writing (fmt).

#include "tailor/io/obj_io.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>
#include <string_view>

#include "tailor/geometry/error.hpp"
#include "tailor/io/file_bytes.hpp"
#include "tailor/io/input_file.hpp"
#include "tailor/io/obj_parser.hpp"

namespace tailor {

MeshData parse_obj(std::string_view text, const std::filesystem::path& source) {
  return parse_obj_text(text, source).mesh;
}

MeshData read_obj(const std::filesystem::path& path) {
  const InputFile file(path);
  return parse_obj(file.bytes(), path);
}

void write_obj(const std::filesystem::path& path, const Positions& vertices,
               const FaceArray& faces) {
  const Index nv = static_cast<Index>(vertices.rows());
  fmt::memory_buffer out;
  out.reserve(static_cast<std::size_t>(nv) * 60 + static_cast<std::size_t>(faces.rows()) * 24);
  for (Index v = 0; v < nv; ++v) {
    const double x = vertices(v, 0), y = vertices(v, 1), z = vertices(v, 2);
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) {
      throw InputError(
          fmt::format("cannot write {}: vertex {} has a non-finite coordinate", path.string(), v));
    }
    fmt::format_to(std::back_inserter(out), "v {:.17g} {:.17g} {:.17g}\n", x, y, z);
  }
  for (Index f = 0; f < faces.rows(); ++f) {
    for (int i = 0; i < 3; ++i) {
      if (faces(f, i) < 0 || faces(f, i) >= nv) {
        throw InputError(
            fmt::format("cannot write {}: face {} has vertex index {} out of range ({} vertices)",
                        path.string(), f, faces(f, i), nv));
      }
    }
    fmt::format_to(std::back_inserter(out), "f {} {} {}\n", faces(f, 0) + 1, faces(f, 1) + 1,
                   faces(f, 2) + 1);
  }
  write_file_bytes(path, std::string_view(out.data(), out.size()));
}

}  // namespace tailor
