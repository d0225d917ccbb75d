#pragma once
/// @file
/// Wavefront OBJ reading and writing (positions and triangle faces only).

#include <filesystem>
#include <string_view>

#include "tailor/geometry/types.hpp"
#include "tailor/mesh/mesh_data.hpp"

namespace tailor {

/// Reads an OBJ file: `v x y z` (extra values such as w or colours ignored) and `f`
/// entries in any of the forms `i`, `i/j`, `i//k`, `i/j/k`, with 1-based or negative
/// (relative) indices. Normals, texture coordinates, groups, materials and comments are
/// ignored. Polygons with more than three vertices are split into triangle fans (one
/// warning per file). Throws InputError naming the file, the line and the problem
/// (missing file, garbage token, non-finite coordinate, index out of range, face with
/// fewer than three vertices or a repeated vertex, unknown statement, no face at all, a
/// line longer than 64 MiB, arrays beyond the memory budget). Numbers are decimal as
/// std::from_chars reads them, with one optional leading '+' (no hex floats, no "+-1");
/// coordinates below the smallest subnormal read as 0. The file is mapped, not read into
/// memory (input_file.hpp); quoted tokens are cut to ~40 bytes (excerpt.hpp).
MeshData read_obj(const std::filesystem::path& path);

/// Parses OBJ text already in memory as read_obj() does; `source` names it in errors.
MeshData parse_obj(std::string_view text, const std::filesystem::path& source);

/// Writes `v` lines with round-trip precision (17 significant digits) and 1-based `f`
/// lines. Throws InputError if the file cannot be written, a coordinate is not finite
/// or a face index is out of range.
void write_obj(const std::filesystem::path& path, const Positions& vertices,
               const FaceArray& faces);

}  // namespace tailor
