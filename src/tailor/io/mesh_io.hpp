#pragma once
/// @file
/// Mesh files by extension: `.obj` or `.ply` (case-insensitive).

#include <filesystem>

#include "tailor/geometry/types.hpp"
#include "tailor/io/obj_io.hpp"
#include "tailor/io/ply_io.hpp"
#include "tailor/mesh/mesh_data.hpp"

namespace tailor {

/// Reads an OBJ or PLY file, chosen by its extension (case-insensitive). Throws
/// InputError on an unknown extension, a missing file ("cannot open") or bad content.
MeshData read_mesh(const std::filesystem::path& path);

/// Writes an OBJ or PLY file (binary little-endian, double coordinates), chosen by the
/// extension. Throws InputError on an unknown extension or a write error.
void write_mesh(const std::filesystem::path& path, const Positions& vertices,
                const FaceArray& faces);

/// True when the path ends in `.obj` or `.ply` (any case).
bool is_mesh_file_name(const std::filesystem::path& path);

}  // namespace tailor
