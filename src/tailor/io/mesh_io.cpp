/// @file
/// Dispatch on the file extension.

#include "tailor/io/mesh_io.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <string>

#include "tailor/geometry/error.hpp"

namespace tailor {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

[[noreturn]] void unknown_extension(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  throw InputError(fmt::format("{}: unknown mesh file extension '{}' (expected .obj or .ply)",
                               path.string(), ext.empty() ? std::string("(none)") : ext));
}

}  // namespace

bool is_mesh_file_name(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".obj" || ext == ".ply";
}

MeshData read_mesh(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".obj") return read_obj(path);
  if (ext == ".ply") return read_ply(path);
  unknown_extension(path);
}

void write_mesh(const std::filesystem::path& path, const Positions& vertices,
                const FaceArray& faces) {
  const std::string ext = lower_extension(path);
  if (ext == ".obj") return write_obj(path, vertices, faces);
  if (ext == ".ply") return write_ply(path, vertices, faces);
  unknown_extension(path);
}

}  // namespace tailor
